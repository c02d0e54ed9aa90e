#pragma once
// Time integration of a dynamic rigid body (docs/METHOD.md "Rigid body motion"). The solver
// accumulates the force and torque on the body (fluid force, contact impulses / Δt, drag) and
// calls step() once per sub-step; static and kinematic bodies are not integrated here.
#include "rigid/RigidBodyInertia.h"
#include "rigid/RigidBodyState.h"
#include "rigid/RigidVelocity.h"

namespace airtrap {

class RigidIntegrator {
public:
    //! Advances a dynamic body by `dt` (s) under `force` (N, world, through the centre of mass),
    //! `torque` (N·m, world, about the centre of mass) and `gravity` (m/s²). Does nothing for an
    //! infinite-mass body.
    //!
    //! Linear motion: semi-implicit (symplectic) Euler, V ← V + Δt (F/M + g), X ← X + Δt V.
    //! Angular motion, in the body frame where I is constant: the torque as a kick,
    //! ω ← ω + Δt I⁻¹ τ, then the torque-free Euler equations by gyroscopicStep(); the
    //! orientation turns by the exponential map of the step's mean ω (advanceOrientation()).
    static void step(RigidBodyState& state, const RigidBodyInertia& inertia, const Vec3d& force,
                     const Vec3d& torque, const Vec3d& gravity, double dt);
    //! The velocity half of step(), so that contacts can act between the two halves. Returns
    //! the angular velocity (world) the orientation should turn with: the step's mean.
    static Vec3d accelerate(RigidBodyState& state, const RigidBodyInertia& inertia,
                            const Vec3d& force, const Vec3d& torque, const Vec3d& gravity,
                            double dt);
    //! The pose half: X ← X + Δt (V + push.linear), q ← exp((turnRate + push.angular) Δt) q,
    //! with the body-frame angular velocity kept. `push` is a contact solver's position-only
    //! correction (RigidContactSolver).
    static void advancePose(RigidBodyState& state, const Vec3d& turnRate, const RigidVelocity& push,
                            double dt);

    //! q ← exp(ω Δt) q, renormalised: the exact rotation for ω constant over the step
    //! (RotationVector), so the orientation neither drifts off unit length (as q + ½Δt ω q does)
    //! nor lags at large ω Δt.
    static Quatd advanceOrientation(const Quatd& orientation, const Vec3d& angularVelocity,
                                    double dt);

    //! Torque-free Euler equations in the body frame, I ω̇ = (I ω) × ω, over `dt` by the
    //! implicit midpoint rule, solved by Newton's method. Exposed for the tests.
    static Vec3d gyroscopicStep(const Mat3d& inertiaBody, const Vec3d& omegaBody, double dt);

private:
    //! The angular part of accelerate(): the new ω; returns the step's mean ω (world).
    static Vec3d spin(RigidBodyState& state, const RigidBodyInertia& inertia, const Vec3d& torque,
                      double dt);
};

} // namespace airtrap
