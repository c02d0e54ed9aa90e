#pragma once
// The bubbles' cost per step at one moment of a bake: the simulation with bubbles against the same
// water without them, both alive at once and stepped in turn, one step each, the order swapped
// every pair. Timing the two in separate runs, each with a new simulation, let the memory layout
// of each run and slow spells of a shared machine fall on one side: the same comparison varied by
// several points between runs. Stepped in turn, both see the same machine and the same cold
// caches after the other's step.
#include "scene/Scene.h"
#include "sim/SimulationState.h"

#include <map>
#include <string>

namespace airtrap::bench {

struct BubbleStepResult {
    int threads = 0;
    int steps = 0;           //!< measured steps of each simulation
    std::size_t bubbles = 0; //!< alive at the end
    double msPerStepOn = 0.0;
    double msPerStepOff = 0.0;
    std::map<std::string, double> phaseMillisecondsOn;  //!< mean per step, with bubbles
    std::map<std::string, double> phaseMillisecondsOff; //!< mean per step, without

    double overheadPercent() const { return 100.0 * (msPerStepOn / msPerStepOff - 1.0); }
};

class BubbleStepComparison {
public:
    //! `scene` with bubbles enabled and a state of it; the comparison drops the bubbles from a
    //! copy of both for the side without.
    BubbleStepComparison(Scene scene, SimulationState start)
        : scene_(std::move(scene)), start_(std::move(start)) {}

    //! Takes `warmupSteps` unmeasured steps of each, then `steps` measured ones.
    BubbleStepResult run(int threads, int steps, int warmupSteps) const;

private:
    Scene scene_;
    SimulationState start_;
};

} // namespace airtrap::bench
