#pragma once
// Weakly compressible SPH (paper §3.1, docs/METHOD.md "Water: weakly compressible SPH" and
// "Impulse-based boundary force"): continuity density (eq. 2) with a periodic Shepard
// re-initialisation, Tait equation of state (eq. 3, γ = 7, c = 10·u_max), Monaghan momentum with
// artificial viscosity (eq. 1), boundary particles for every rigid body, and the contact impulse of
// the impulse-based boundary force (eq. 4) for water approaching a body.
#include "bubbles/BubbleDynamics.h"
#include "rigid/RigidBody.h"
#include "scene/Scene.h"
#include "sim/SimulationState.h"
#include "sph/BoundaryModel.h"
#include "sph/CubicSplineKernel.h"
#include "sph/InteractionPass.h"
#include "sph/NeighborGrid.h"
#include "sph/RigidCoupling.h"
#include "sph/StepPhases.h"

#include <optional>
#include <vector>

namespace airtrap {

//! What one step did, for the time-step controller and the blow-up guard.
struct StepReport {
    double timeStep = 0.0;            //!< s, Δt actually taken
    double maxAcceleration = 0.0;     //!< m/s², without contact impulses (feeds the next Δt)
    double maxSpeed = 0.0;            //!< m/s, at the start of the step
    double maxDensityDeviation = 0.0; //!< max |ρ/ρ₀ − 1| after the step
    std::size_t removedParticles = 0; //!< left the domain this step
    bool nonFinite = false;           //!< a NaN or infinity appeared
};

class WcsphSolver {
public:
    //! `bodies` holds the scenery first (container, obstacles: static, not in the state), then
    //! `bodies.size() − sceneryCount` bodies whose states SimulationState::bodies carries in
    //! the same order. With bubbles enabled, the state's bubbles join them as bodies.
    WcsphSolver(const SolverSettings& settings, const Aabb& domain, std::vector<RigidBody> bodies,
                std::size_t sceneryCount = 0, const BubbleSettings& bubbles = {});

    // The phases of a step, in the order Simulation::takeStep() runs them (docs/ARCHITECTURE.md,
    // "The step"). Each reads the water as the phases before it left it.

    //! Whether the bodies' boundary particles must be placed this step: a body moves, or bubbles
    //! exist or have just been deleted.
    bool bodiesToPlace(const SimulationState& state) const;
    //! Sorts the particles by cell onto grid(), dropping those outside the domain; reports how
    //! many left and the largest speed (for Δt), found in the same sweep.
    void sortByCell(ParticleSet& fluid, StepReport& report);
    //! Copies the state's bodies into bodies() (kinematic ones on their paths), makes the
    //! bubbles' bodies follow the state's bubbles, and places their boundary particles.
    void placeBodies(SimulationState& state);
    //! Marks the water near the moving bodies' boundary particles on this step's grid.
    void pairMovingBoundary();
    //! Δt from the CFL condition and the last step's largest acceleration, at most
    //! `timeToFrameEnd`; a frame's end is met exactly without a sliver of a last step.
    double chooseTimeStep(double maxSpeed, double lastMaxAcceleration, double timeToFrameEnd) const;
    //! Every shepard_interval steps the Shepard re-initialisation; then ρ advanced by the
    //! continuity equation (eq. 2) and the pressures of the equation of state (eq. 3).
    void computeDensities(ParticleSet& fluid, std::uint64_t step, double dt, StepReport& report);
    //! The momentum equation (eq. 1) with the boundary force's contact impulses (eq. 4).
    void computeForces(const ParticleSet& fluid, double dt, StepReport& report);
    //! Whether the water around the bubbles is to be measured this step.
    bool bubbleSurroundingsDue(const SimulationState& state) const;
    //! Measures the water around the bubbles (BubbleDynamics) on this step's grid.
    void measureBubbleSurroundings(SimulationState& state);
    //! Whether any body moves under the water's forces.
    bool hasDynamicBodies() const { return boundary_.hasDynamicBodies(); }
    //! The water's force on each dynamic body's boundary particles, from this step's pass.
    void computeBodyReactions(const ParticleSet& fluid, double dt);
    //! The dynamic bodies' contacts and motion over `dt` under those reactions, with the
    //! bubbles' rise, drag and pair impulses; false when a body's state is no longer finite.
    //! Touches no water, so it may run beside integrate().
    bool moveDynamicBodies(SimulationState& state, double dt);
    //! v ← v + Δt a, x ← x + Δt v; returns whether a NaN or infinity appeared.
    bool integrate(ParticleSet& fluid, double dt);

    //! Puts the kinematic bodies of `state` where their paths have them at state.time.
    void followPaths(SimulationState& state);

    //! Tait equation of state, p = B((ρ/ρ₀)^γ − 1), clamped at 0 so the free surface does not
    //! pull particles into clumps.
    float pressure(float density) const;
    //! The density at which the pressure equals p (inverse of the equation of state).
    float densityForPressure(double pressure) const;

    const CubicSplineKernel& kernel() const { return kernel_; }
    float particleMass() const { return mass_; }
    double speedOfSound() const { return speedOfSound_; }
    const std::vector<RigidBody>& bodies() const { return bodies_; }
    const RigidCoupling& coupling() const { return coupling_; }
    const BoundaryModel& boundary() const { return boundary_; }
    const NeighborGrid& grid() const { return grid_; }
    //! The water's positions as the last step sorted them onto grid(), before it moved them.
    const PositionArrays& sortedPositions() const { return sortedPositions_; }
    //! Index in bodies() of the first bubble's body; the bodies before it are the scene's.
    std::size_t firstBubbleBody() const { return firstBubble_; }
    StepPhases& phases() { return phases_; }
    //! Heap bytes held by the solver's grids and scratch arrays (not the particle state).
    std::size_t allocatedBytes() const;

private:
    //! Re-initialises every density by Shepard interpolation, on this step's sorted particles.
    void shepardFilter(ParticleSet& fluid);
    //! ρ ← max(ρ₀, ρ + Δt dρ/dt) and the pressure terms p/ρ²; returns max |ρ/ρ₀ − 1|.
    double advanceDensities(ParticleSet& fluid, double dt);
    InteractionConstants interactionConstants() const;
    //! What the interaction passes read: the water, its sorted positions, the grid, the bodies.
    InteractionInputs inputs(const ParticleSet& fluid) const;
    //! Copies the moved bodies back into the state; returns false when one is not finite.
    bool storeMovedBodies(SimulationState& state) const;

    SolverSettings settings_;
    CubicSplineKernel kernel_;
    float spacing_;
    float mass_;
    double speedOfSound_;
    double tait_; //!< B = ρ₀c²/γ
    Aabb gridDomain_;
    std::vector<RigidBody> bodies_;
    std::size_t sceneryCount_;
    std::size_t firstBubble_; //!< index in bodies_ of the first bubble's body
    bool anyBodyMoves_ = false;
    std::optional<BubbleDynamics> bubbles_;
    BoundaryModel boundary_;
    RigidCoupling coupling_;
    NeighborGrid grid_;
    InteractionPass passes_;
    StepPhases phases_;

    // Per-particle scratch, in the sorted order of the current step.
    PositionArrays sortedPositions_;
    NeighborList neighbors_;
    std::vector<float> pressureOverDensity2_; //!< p/ρ², the pressure term of eq. 1
    std::vector<float> densityRates_;         //!< dρ/dt (eq. 2)
    std::vector<Vec3f> accelerations_;        //!< dv/dt (eq. 1 + contact impulses)
    ParticleSet reorderScratch_;
    ContactRecords contacts_;      //!< impulses from dynamic bodies, for their reaction
    std::vector<Vec3d> reactions_; //!< N, the water's force on each boundary particle
};

} // namespace airtrap
