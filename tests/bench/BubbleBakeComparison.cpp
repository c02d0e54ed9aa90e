#include "BubbleBakeComparison.h"

#include "core/Interrupter.h"
#include "core/ThreadLimit.h"
#include "sim/Simulation.h"
#include "sim/StepPhases.h"

#include <algorithm>
#include <chrono>

namespace airtrap::bench {

namespace {

double secondsToAdvance(Simulation& simulation, Interrupter& never) {
    const auto start = std::chrono::steady_clock::now();
    simulation.advanceFrame(never);
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

double bubblePhaseSeconds(const StepPhases& phases) {
    return phases.seconds(StepPhases::BubbleForces) + phases.seconds(StepPhases::BubblePockets) +
           phases.seconds(StepPhases::BubbleDeletion) + phases.seconds(StepPhases::Bodies);
}

} // namespace

BubbleBakeResult BubbleBakeComparison::run(int threads, double snapshotTime) const {
    ThreadLimit limit(threads);
    Scene without = scene_;
    without.bubbles.enabled = false;
    Simulation on(scene_);
    Simulation off(without);
    Interrupter never;
    BubbleBakeResult result;
    result.threads = limit.threads();
    for (int frame = 0; frame < frames_; ++frame) {
        result.secondsOff += secondsToAdvance(off, never);
        result.secondsOn += secondsToAdvance(on, never);
        // The simulation restarts its phase clocks every frame.
        result.bubblePhaseSeconds += bubblePhaseSeconds(on.phases());
        result.mostBubblesAlive = std::max(result.mostBubblesAlive, on.state().bubbles.size());
        if (!result.snapshot && on.state().time >= snapshotTime)
            result.snapshot = on.state();
    }
    result.frames = frames_;
    result.particles = on.state().fluid.size();
    result.stepsOn = on.state().steps;
    result.stepsOff = off.state().steps;
    result.bubblesCreated = on.state().nextBubbleId;
    return result;
}

} // namespace airtrap::bench
