#pragma once
// The last steps of a frame, shared by both pressure solvers.
#include <algorithm>

namespace airtrap {

//! The step to take when the water allows `dt` s and the frame ends in `timeToFrameEnd` s: the
//! frame's end exactly when it is within reach, else two even steps rather than a full one and
//! a sliver (a tiny last step wastes a whole step's passes).
inline double landOnFrame(double dt, double timeToFrameEnd) {
    if (dt >= timeToFrameEnd)
        return timeToFrameEnd;
    if (2.0 * dt > timeToFrameEnd)
        return 0.5 * timeToFrameEnd;
    return dt;
}

} // namespace airtrap
