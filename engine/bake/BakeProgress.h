#pragma once
// How far a bake has come: Baker reports it after every step and every frame; the command
// line's progress line and the editor's status bar show it.
#include <cstddef>

namespace airtrap {

struct BakeProgress {
    int frame = 0; //!< the frame being computed
    int lastFrame = 0;
    double simTime = 0.0;       //!< s
    double frameFraction = 0.0; //!< 0–1 of the current frame
    double stepsPerSecond = 0.0;
    std::size_t particles = 0;
    std::size_t bubbles = 0;  //!< alive after the step
    double etaSeconds = -1.0; //!< negative until a frame has finished
};

} // namespace airtrap
