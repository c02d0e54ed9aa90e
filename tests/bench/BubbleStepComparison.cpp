#include "BubbleStepComparison.h"

#include "core/ThreadLimit.h"
#include "sim/Simulation.h"
#include "sim/StepPhases.h"

#include <chrono>
#include <limits>

namespace airtrap::bench {

namespace {

constexpr double kNoFrameEnd = std::numeric_limits<double>::infinity();

double secondsToStep(Simulation& simulation) {
    const auto start = std::chrono::steady_clock::now();
    simulation.step(kNoFrameEnd);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::map<std::string, double> phaseMilliseconds(Simulation& simulation, int steps) {
    std::map<std::string, double> phases;
    for (int phase = 0; phase < StepPhases::Count; ++phase)
        phases[std::string(StepPhases::kNames[phase])] =
            1000.0 * simulation.phases().seconds(static_cast<StepPhases::Phase>(phase)) / steps;
    return phases;
}

} // namespace

BubbleStepResult BubbleStepComparison::run(int threads, int steps, int warmupSteps) const {
    ThreadLimit limit(threads);
    Scene without = scene_;
    without.bubbles.enabled = false;
    SimulationState water = start_;
    water.bubbles.clear();
    Simulation on(scene_, start_);
    Simulation off(without, water);
    for (int step = 0; step < warmupSteps; ++step) {
        on.step(kNoFrameEnd);
        off.step(kNoFrameEnd);
    }
    on.phases().reset();
    off.phases().reset();
    double secondsOn = 0.0;
    double secondsOff = 0.0;
    for (int step = 0; step < steps; ++step) {
        // Each goes first in every other pair: the first of a pair starts on caches the other's
        // step has left.
        if (step % 2 == 0) {
            secondsOn += secondsToStep(on);
            secondsOff += secondsToStep(off);
        } else {
            secondsOff += secondsToStep(off);
            secondsOn += secondsToStep(on);
        }
    }
    BubbleStepResult result;
    result.threads = limit.threads();
    result.steps = steps;
    result.bubbles = on.state().bubbles.size();
    result.msPerStepOn = 1000.0 * secondsOn / steps;
    result.msPerStepOff = 1000.0 * secondsOff / steps;
    result.phaseMillisecondsOn = phaseMilliseconds(on, steps);
    result.phaseMillisecondsOff = phaseMilliseconds(off, steps);
    return result;
}

} // namespace airtrap::bench
