#pragma once
// The bodies' half of the two-way coupling (paper §3.3.1, eq. 4): each dynamic body takes the
// water's reaction — the sum over its boundary particles of the pressure, friction and contact
// impulses they gave the water, with the torque about its centre of mass — plus gravity, then
// its contacts with other bodies, and moves. No buoyancy term: buoyancy is what the pressure on
// the body's underside adds up to.
#include "rigid/RigidBody.h"
#include "rigid/RigidContactSolver.h"
#include "sph/BoundaryModel.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace airtrap {

class RigidCoupling {
public:
    //! s. Velocity-level contact impulses let a stack of bodies lean by a little at every step
    //! they rest on each other, and the longer the step the more: a stack of three boxes leaned
    //! 0.022 rad at DFSPH's 5 ms steps, 0.0045 at 1 ms, 0.0012 at 0.5 ms (docs/VALIDATION.md
    //! "Bodies with DFSPH"). Longer steps are split for the bodies, as rigid-body engines
    //! sub-step their contacts (Macklin et al., "Small Steps in Physics Simulation", SCA 2019).
    //! No WCSPH sample's step is split: their cache frames kept the same bits.
    static constexpr double kMaxContactStep = 1.0e-3;

    //! `spacing` (m) of the particles sets the contact solver's tolerances.
    RigidCoupling(const Vec3d& gravity, double spacing);

    //! Changes the bodies' velocities once the water's force and gravity have acted, before
    //! contacts: the bubbles' own forces. `before` holds each body's linear velocity as the
    //! sub-step of `dt` s began, before the water's force and gravity.
    using ExtraForces = std::function<void(std::vector<RigidBody>& bodies,
                                           const std::vector<Vec3d>& before, double dt)>;

    //! Moves the dynamic bodies of `bodies` over `dt` (s). `reactions` holds the water's force
    //! on each sorted particle of the boundary's moving layer (InteractionPass::bodyReactions).
    void advance(std::vector<RigidBody>& bodies, const BoundaryModel& boundary,
                 const std::vector<Vec3d>& reactions, double dt,
                 const ExtraForces& extraForces = {});
    //! See RigidContactSolver::setBubblesFrom.
    void setBubblesFrom(std::size_t index) {
        contacts_.setBubblesFrom(index);
        bubblesFrom_ = index;
    }
    //! Moves the bubbles with the water they carry along (docs/METHOD.md "Bubbles with DFSPH"):
    //! (m + mₐ) dv/dt = F + m g, with mₐ half the water a bubble displaces (`restDensity`, kg/m³),
    //! and over each step at the velocity it began with, the one the water was solved against.
    //! For the divergence-free solver, whose step hands a bubble the water's whole reaction at
    //! once; 0 (the default) moves them on m alone, with the velocity each sub-step ends with.
    void setBubbleAddedMass(double restDensity) { bubbleWaterDensity_ = restDensity; }

private:
    //! One sub-step of advance(): the water's force, gravity, `extraForces`, the contacts, the
    //! move.
    void advanceSubstep(std::vector<RigidBody>& bodies, double dt, const ExtraForces& extraForces);
    //! Sums the reactions per body, in the boundary's sorted order so the sum is deterministic.
    void sumReactions(const std::vector<RigidBody>& bodies, const BoundaryModel& boundary,
                      const std::vector<Vec3d>& reactions);
    //! Rewrites each bubble's force so that the integrator's F/m + g is (F + m g) / (m + mₐ).
    void addBubblesAddedMass(const std::vector<RigidBody>& bodies);
    //! Puts each bubble where its velocity at the step's start (`startVelocities`, from
    //! bubblesFrom_ on) takes it from `startPositions` over `dt` s; its new velocity stays, for
    //! the next step.
    void moveBubblesAsSolved(std::vector<RigidBody>& bodies,
                             const std::vector<Vec3d>& startPositions,
                             const std::vector<Vec3d>& startVelocities, double dt) const;

    Vec3d gravity_;
    RigidContactSolver contacts_;
    std::size_t bubblesFrom_ = SIZE_MAX;
    double bubbleWaterDensity_ = 0.0; //!< kg/m³; 0: the bubbles move on their own mass

    std::vector<Vec3d> forces_;                //!< N, the water's force on each body this step
    std::vector<Vec3d> torques_;               //!< N·m, about each body's centre of mass
    std::vector<Vec3d> bubbleStartPositions_;  //!< m, of this step's bubbles, from bubblesFrom_
    std::vector<Vec3d> bubbleStartVelocities_; //!< m/s
};

} // namespace airtrap
