// Engine code that includes the engine's and base's headers: compiled with
// the same setup as engine_sees_ladder.cpp, it must compile, so that the
// other's failure is the wall and not a broken setup.
#include "jl/base/geometry.h"
#include "jl/engine/world.h"
