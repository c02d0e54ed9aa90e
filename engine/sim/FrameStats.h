#pragma once
#include "bubbles/BubbleTally.h"

#include <cstdint>
#include <map>
#include <string>

namespace airtrap {

//! What one frame cost and what it looks like in numbers; stored with the frame in the cache and
//! shown by `info --json` (docs/CLI.md "info") and the editor's status bar.
struct FrameStats {
    double wallSeconds = 0.0;                   //!< wall-clock time of the frame's steps
    std::map<std::string, double> phaseSeconds; //!< per phase: neighbours, density, forces, ...
    std::uint64_t stepsInFrame = 0;
    double maxSpeed = 0.0;    //!< m/s over the water particles at the frame's end
    double meanDensity = 0.0; //!< kg/m³
    BubbleTally bubbles;      //!< bubbles created and deleted (per rule) during the frame

    bool operator==(const FrameStats& other) const = default;
};

} // namespace airtrap
