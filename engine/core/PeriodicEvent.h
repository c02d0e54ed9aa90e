#pragma once
// Work done every so often in simulated time rather than every so many steps, so that a solver
// with longer steps does it as often: due in the step [from, to) when a multiple of the period
// falls in it. Decided from the times alone, which the cache keeps, so a resumed bake does it at
// the same steps.
#include <cmath>

namespace airtrap {

//! Whether a multiple of `period` (s, > 0) lies in [from, to); the step from t = 0 always
//! qualifies.
inline bool periodDue(double from, double to, double period) {
    return from <= 0.0 || std::floor(to / period) != std::floor(from / period);
}

} // namespace airtrap
