#pragma once
// The simulation: owns the state and steps it in the order of the paper's Table 1 (one function,
// takeStep(); docs/ARCHITECTURE.md, "The step"), frame after frame, with the health checks that
// stop a bake that blows up.
#include "bubbles/BubbleDeletion.h"
#include "bubbles/BubbleSpawner.h"
#include "core/Interrupter.h"
#include "scene/Scene.h"
#include "sim/FrameStats.h"
#include "sim/InflowEmitter.h"
#include "sim/RigidWorld.h"
#include "sim/SimulationState.h"
#include "sim/StepPhases.h"
#include "sph/PressureSolver.h"

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace airtrap {

class Simulation {
public:
    //! Builds the initial state (frame 1, t = 0) from the scene. The scene must be valid.
    explicit Simulation(Scene scene);
    //! Continues from a cached state of the same scene.
    Simulation(Scene scene, SimulationState resumeFrom);
    ~Simulation();
    Simulation(const Simulation&) = delete;
    Simulation& operator=(const Simulation&) = delete;

    const Scene& scene() const { return scene_; }
    const SimulationState& state() const { return state_; }
    int frame() const { return state_.frame; }

    enum class Advance { FrameDone, Interrupted };
    //! Called after every step with the share (0–1) of the frame done.
    using StepObserver = std::function<void(double frameFraction)>;

    //! Steps until the next frame's time is reached exactly. Checks the interrupter after every
    //! step; when it asks to stop, returns Interrupted and the state is mid-frame (not to be
    //! cached). Throws Error(SimulationBlowUp) naming the frame and likely cause.
    Advance advanceFrame(Interrupter& interrupter, const StepObserver& onStep = {});

    //! Takes one solver step of at most `maxTimeStep` seconds outside the frame bookkeeping, for
    //! benchmarks and tests; the state's time advances but no frame is completed.
    StepReport step(double maxTimeStep);

    //! What the bake should tell the user since the last call: particles that left the domain,
    //! solves that did not converge, a step held at its minimum, water faster than WCSPH's
    //! max_speed. Each names the frame.
    std::vector<std::string> takeNotices();

    //! Statistics of the last completed frame (or of the initial state).
    const FrameStats& lastFrameStats() const { return lastFrameStats_; }

    //! The water's pressure solver, for benchmarks and tests that look into it.
    const PressureSolver& solver() const { return *water_; }
    //! The rigid bodies, bubbles' included, as the last step placed and moved them.
    const RigidWorld& bodies() const { return bodies_; }
    //! Wall-clock seconds per phase of the steps taken since the frame began (or since reset).
    StepPhases& phases() { return phases_; }

private:
    //! Why the water may have compressed beyond the blow-up guard, naming what to change.
    std::string densityErrorCause(const StepReport& report) const;
    //! Throws Error(SimulationBlowUp) naming the frame and the likely cause.
    void checkHealth(const StepReport& report, double timeToFrameEnd, int frame, std::size_t lost,
                     std::size_t particlesAtStart) const;
    //! Adds a DFSPH step's solves to the frame's; throws Error(SimulationBlowUp) when the density
    //! solve has not converged for many steps in a row.
    void tallySolve(const StepReport& report, int frame, PressureSolveStats& solve);
    //! The notices of a finished frame.
    void noteFrame(int frame, std::size_t lost, double fastest, const PressureSolveStats& solve);
    //! Adds the inflow layers due during the step that just went from `from` to `to`.
    void emitInflow(double from, double to);
    //! One step of at most `timeToFrameEnd` seconds, in the paper's Table 1 order: neighbours,
    //! particle interactions, rigid and bubble interactions and the move, then time, kinematic
    //! paths and inflow, bubble deletion and, every bubbles.pocket_interval seconds, creation.
    //! `frameEnd` is the time the frame under way ends at (s).
    StepReport takeStep(double timeToFrameEnd, double frameEnd);
    //! The dynamic bodies' reactions and motion beside the water's integration; false when
    //! either is no longer finite.
    bool moveBodiesAndWater(double dt);
    //! Applies the deletion rules after a step of `dt` seconds and counts what they deleted.
    void deleteBubbles(double dt);
    //! Turns air pockets of the last step's grid into bubbles born in `frame`, within what is
    //! left of the frame's creation limit.
    void createBubbles(int frame);

    Scene scene_;
    SimulationState state_;
    FrameStats lastFrameStats_;
    StepPhases phases_;
    std::unique_ptr<PressureSolver> water_;
    RigidWorld bodies_;
    std::vector<InflowEmitter> emitters_;
    std::optional<BubbleDeletion> bubbleDeletion_;
    std::optional<BubbleSpawner> bubbleSpawner_;
    BubbleTally frameBubbles_; //!< created and deleted during the frame under way
    int steppedFrame_ = -1;    //!< frame whose time step() last stepped in
    std::vector<std::string> notices_;
    int unconvergedInARow_ = 0;
    bool warnedMinimumStep_ = false;
    bool warnedMaxSpeed_ = false;
};

} // namespace airtrap
