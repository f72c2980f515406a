// Engine code that includes a ladder header: the engine does not use the
// ladder, so this must fail to compile with "jl/ladder/ladder.h" not found
// (the test part_wall_engine_sees_ladder).
#include "jl/ladder/ladder.h"
