#include "jl/engine/kept_evaluation.h"

#include "jl/engine/world.h"

namespace jl {

void KeptEvaluation::keep(const World& w, const Dynamics& d, double t, const Powers& powers) {
    kept_ = true;
    t_ = t;
    revision_ = w.revision();
    gravity_ = w.gravity;
    q_ = w.q;
    v_ = w.v;
    a_ = w.a;
    forces_ = d.last();
    powers_ = powers;
}

const Powers* KeptEvaluation::recall(World& w, Dynamics& d, double t) const {
    // Exact comparisons on purpose: only the very same inputs give the very
    // same evaluation. Not with resting contacts: their rows' matrix (what
    // the contacts' release test reads) is not kept, and an evaluation of
    // another state since may have replaced it.
    if (!kept_ || !w.contacts().empty() || t != t_ || w.revision() != revision_ || w.gravity != gravity_ ||
        w.q.size() != q_.size() || w.v.size() != v_.size() || w.q != q_ || w.v != v_)
        return nullptr;
    w.a = a_;
    d.restoreLast(forces_);
    return &powers_;
}

}  // namespace jl
