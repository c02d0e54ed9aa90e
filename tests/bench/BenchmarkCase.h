#pragma once
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <map>
#include <optional>
#include <string>

namespace airtrap::bench {

//! One measured run: a scene at one resolution on a number of threads for a number of steps.
struct BenchmarkResult {
    std::string scene;
    std::size_t particles = 0;
    int threads = 0;
    int steps = 0;
    double wallSeconds = 0.0;
    double particleUpdatesPerSecond = 0.0;
    double neighborsPerParticle = 0.0;
    double bytesPerParticle = 0.0;       //!< peak resident growth over the run / particles
    double engineBytesPerParticle = 0.0; //!< bytes the engine's arrays hold / particles
    std::map<std::string, double> phaseMilliseconds; //!< mean per step
    std::size_t bubbles = 0;                         //!< alive at the end of the run
};

class BenchmarkCase {
public:
    BenchmarkCase(std::string name, Scene scene)
        : name_(std::move(name)), scene_(std::move(scene)) {}
    //! Starts from `start` (a state of `scene`) rather than from the scene's t = 0.
    BenchmarkCase(std::string name, Scene scene, SimulationState start)
        : name_(std::move(name)), scene_(std::move(scene)), start_(std::move(start)) {}

    //! Builds the simulation, takes `warmupSteps` unmeasured steps, then `steps` measured ones.
    BenchmarkResult run(int threads, int steps, int warmupSteps) const;

private:
    std::string name_;
    Scene scene_;
    std::optional<SimulationState> start_;
};

} // namespace airtrap::bench
