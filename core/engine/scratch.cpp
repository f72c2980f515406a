// The engine's scratch holders, instantiated where their contents are defined.
#include "scratch.h"

#include "jl/engine/fresh.h"

namespace jl {

template class Fresh<PinSolver>;
template class Fresh<Scratch>;

}  // namespace jl
