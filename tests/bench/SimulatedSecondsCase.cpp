#include "SimulatedSecondsCase.h"

#include "ProcessMemory.h"
#include "core/Interrupter.h"
#include "core/ThreadLimit.h"
#include "sim/Simulation.h"

#include <chrono>
#include <cmath>
#include <stdexcept>

namespace airtrap::bench {

namespace {

//! Adds a finished frame's figures to the bake's.
void addFrame(const FrameStats& frame, SimulatedSecondsResult& result,
              std::uint64_t& divergenceIterations, std::uint64_t& densityIterations) {
    result.steps += frame.stepsInFrame;
    divergenceIterations += frame.pressureSolve.divergenceIterations;
    densityIterations += frame.pressureSolve.densityIterations;
    result.unconvergedSteps += frame.pressureSolve.unconvergedSteps;
    for (const auto& [phase, seconds] : frame.phaseSeconds)
        result.phaseMilliseconds[phase] += 1000.0 * seconds;
}

} // namespace

SimulatedSecondsResult SimulatedSecondsCase::run(int threads, double seconds) const {
    ThreadLimit limit(threads);
    Scene scene = scene_;
    const int framesNeeded = int(std::ceil(seconds * scene.frames.fps - 1e-9));
    scene.frames.endFrame = std::max(scene.frames.endFrame, 1 + framesNeeded);
    ProcessMemory::resetPeak();
    const std::size_t baseline = ProcessMemory::residentBytes();

    Simulation simulation(scene);
    SimulatedSecondsResult result;
    std::uint64_t divergenceIterations = 0;
    std::uint64_t densityIterations = 0;
    Interrupter interrupter;
    const auto start = std::chrono::steady_clock::now();
    for (int frame = 0; frame < framesNeeded; ++frame) {
        if (simulation.advanceFrame(interrupter) != Simulation::Advance::FrameDone)
            throw std::runtime_error(name_ + ": the bake was interrupted");
        addFrame(simulation.lastFrameStats(), result, divergenceIterations, densityIterations);
    }
    result.wallSeconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    result.scene = name_;
    result.method = scene.solver.method;
    result.particles = simulation.state().fluid.size();
    result.threads = limit.threads();
    result.simulatedSeconds = simulation.state().time;
    const double steps = double(std::max<std::uint64_t>(1, result.steps));
    result.divergenceIterationsPerStep = double(divergenceIterations) / steps;
    result.densityIterationsPerStep = double(densityIterations) / steps;
    for (auto& [phase, ms] : result.phaseMilliseconds)
        ms /= steps;
    const double n = double(std::max<std::size_t>(1, result.particles));
    result.bytesPerParticle = double(ProcessMemory::peakResidentBytes() - baseline) / n;
    result.engineBytesPerParticle =
        double(simulation.solver().allocatedBytes() + simulation.state().fluid.allocatedBytes()) /
        n;
    return result;
}

} // namespace airtrap::bench
