#pragma once
#include "scene/Scene.h"

#include <cstdint>
#include <map>
#include <string>

namespace airtrap::bench {

//! One bake of a number of simulated seconds with one pressure solver: what an artist waits for.
struct SimulatedSecondsResult {
    std::string scene;
    std::string method; //!< solver.method
    std::size_t particles = 0;
    int threads = 0;
    double simulatedSeconds = 0.0;
    double wallSeconds = 0.0;
    std::uint64_t steps = 0;
    double divergenceIterationsPerStep = 0.0; //!< DFSPH only
    double densityIterationsPerStep = 0.0;    //!< DFSPH only
    std::uint64_t unconvergedSteps = 0;       //!< DFSPH density solves stopped at max_iterations
    double bytesPerParticle = 0.0;            //!< peak resident growth over the bake / particles
    double engineBytesPerParticle = 0.0;      //!< bytes the engine's arrays hold / particles
    std::map<std::string, double> phaseMilliseconds; //!< mean per step

    double wallPerSimulatedSecond() const {
        return simulatedSeconds > 0.0 ? wallSeconds / simulatedSeconds : 0.0;
    }
};

class SimulatedSecondsCase {
public:
    SimulatedSecondsCase(std::string name, Scene scene)
        : name_(std::move(name)), scene_(std::move(scene)) {}

    //! Bakes whole frames from t = 0 until `seconds` are simulated (the scene's end frame is
    //! extended if it comes first), with nothing written: the solver's time alone.
    SimulatedSecondsResult run(int threads, double seconds) const;

private:
    std::string name_;
    Scene scene_;
};

} // namespace airtrap::bench
