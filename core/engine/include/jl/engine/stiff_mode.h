// The fastest rate in the motion of a world, what makes it and where: the
// rate an explicit step must resolve (docs/model.md section 6.3), said when
// a run fails or crawls, so that the user knows what sets the step and what
// to change, rather than being sent to look for causes the scene lacks.
#pragma once

#include "jl/engine/world.h"

#include <Eigen/Core>

#include <string>

namespace jl {

struct StiffMode {
    double rate = 0;     // 1/s: a vibration's angular frequency, or a damping's decay rate
    bool decay = false;  // damping over mass or inertia, not a vibration
    std::string what;    // "the spring 0 on body 1 (1e+07 N/m on 1e-06 kg)"; empty: nothing moves fast
};

// Each source of a fast rate, the fastest of them: the rocking of a body on
// its pins under tension (the bound of fastestVibration), a spring on the
// bodies it joins (sqrt(k / m)), and a damping's decay (air drag c / m and
// c / I, a hinge's or a spring's damper) on the lightest body it acts on.
StiffMode stiffestMode(const World& w, const Eigen::VectorXd& pinForces);

// "the spring 0 ... : 3.2e+06 rad/s, a period of 2e-06 s" or "...: decays
// at 1e+09 per s, in 1e-09 s": the mode as a sentence's clause.
std::string describe(const StiffMode& mode);

}  // namespace jl
