#pragma once
#include "bubbles/BubbleTally.h"

#include <cstdint>
#include <map>
#include <string>

namespace airtrap {

//! A divergence-free bake's solves over one frame (all zero for WCSPH).
struct PressureSolveStats {
    std::uint64_t steps = 0;
    std::uint64_t divergenceIterations = 0; //!< summed over the steps
    std::uint64_t densityIterations = 0;    //!< summed over the steps
    double meanDensityError = 0.0;          //!< average compression a step's solve left, mean
    double maxDensityError = 0.0;           //!< the same, the largest of the frame
    std::uint64_t unconvergedSteps = 0;     //!< steps whose density solve hit max_iterations

    double meanIterations(std::uint64_t iterations) const {
        return steps > 0 ? double(iterations) / double(steps) : 0.0;
    }
    bool operator==(const PressureSolveStats& other) const = default;
};

//! What one frame cost and what it looks like in numbers; stored with the frame in the cache and
//! shown by `info --json` (docs/CLI.md "info") and the editor's status bar.
struct FrameStats {
    double wallSeconds = 0.0;                   //!< wall-clock time of the frame's steps
    std::map<std::string, double> phaseSeconds; //!< per phase: neighbours, density, forces, ...
    std::uint64_t stepsInFrame = 0;
    double maxSpeed = 0.0;    //!< m/s over the water particles at the frame's end
    double meanDensity = 0.0; //!< kg/m³
    BubbleTally bubbles;      //!< bubbles created and deleted (per rule) during the frame
    PressureSolveStats pressureSolve;

    bool operator==(const FrameStats& other) const = default;
};

} // namespace airtrap
