#pragma once
// The paper's own measure of what the bubbles cost (§5, pouring water: they "increase the
// simulation time by 1.9 %"): a whole bake from the first frame with bubbles and the same bake
// without. The two bakes advance one frame each in turn, so a slow spell of a shared machine
// falls on both; their flows part ways, so the time steps they take may differ, and that
// difference is part of the cost.
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <cstdint>
#include <optional>

namespace airtrap::bench {

struct BubbleBakeResult {
    int frames = 0;
    int threads = 0;
    std::size_t particles = 0; //!< of the bake with bubbles, at its end
    double secondsOn = 0.0;
    double secondsOff = 0.0;
    std::uint64_t stepsOn = 0;
    std::uint64_t stepsOff = 0;
    std::size_t bubblesCreated = 0;
    std::size_t mostBubblesAlive = 0;
    //! Seconds the bake with bubbles spent in the bubbles' own phases (water search, pockets,
    //! deletion and the bodies phase, which only bubbles use in this scene).
    double bubblePhaseSeconds = 0.0;
    //! The bake with bubbles at the first frame end at or after the snapshot time.
    std::optional<SimulationState> snapshot;

    double overheadPercent() const { return 100.0 * (secondsOn / secondsOff - 1.0); }
    double msPerStepOn() const { return 1000.0 * secondsOn / double(stepsOn); }
    double msPerStepOff() const { return 1000.0 * secondsOff / double(stepsOff); }
};

class BubbleBakeComparison {
public:
    //! `scene` with bubbles enabled; its `frames` first frames are baked both ways.
    BubbleBakeComparison(Scene scene, int frames) : scene_(std::move(scene)), frames_(frames) {}

    //! Bakes on `threads` threads (0: all) and keeps the state at `snapshotTime` seconds.
    BubbleBakeResult run(int threads, double snapshotTime) const;

private:
    Scene scene_;
    int frames_;
};

} // namespace airtrap::bench
