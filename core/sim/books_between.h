// The energy books between the two ends of a step, for a frame read off the
// step's interpolant or an event located inside it. Private to the library.
#pragma once

#include "jl/engine/dynamics.h"
#include "jl/engine/stepper.h"

namespace jl {

// The energy books at the fraction s of a step of length h: cubic Hermite in
// time from their values and rates (the powers) at both ends.
inline Ledger ledgerBetween(const Ledger& l0, const Powers& p0, const Ledger& l1, const Powers& p1, double h,
                            double s) {
    const double s2 = s * s, s3 = s2 * s;
    const auto books = [&](double b0, double r0, double b1, double r1) {
        return (2 * s3 - 3 * s2 + 1) * b0 + (s3 - 2 * s2 + s) * h * r0 + (-2 * s3 + 3 * s2) * b1 + (s3 - s2) * h * r1;
    };
    return {books(l0.held, p0.held, l1.held, p1.held), books(l0.user, p0.user, l1.user, p1.user),
            books(l0.damping, p0.damping, l1.damping, p1.damping)};
}

}  // namespace jl
