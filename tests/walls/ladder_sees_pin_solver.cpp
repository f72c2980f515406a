// Ladder code that includes the pin solver's header: the solver is private
// to the engine (core/engine/pin_solver.h, outside its include root), so
// this must fail to compile with "jl/engine/pin_solver.h" not found (the
// test part_wall_ladder_sees_pin_solver).
#include "jl/engine/pin_solver.h"
