#include "sph/RigidCoupling.h"

#include "rigid/RigidIntegrator.h"

#include <algorithm>
#include <cmath>

namespace airtrap {
namespace {

RigidContactSolver::Settings contactSettings(double spacing) {
    RigidContactSolver::Settings settings;
    // Half a spacing of look-ahead: a body falls less than that in one step at any speed the
    // time-step limit allows (|v| Δt ≤ λ h |v| / (c + |v|) with c = 10 u_max).
    settings.margin = 0.5 * spacing;
    settings.allowedPenetration = 0.02 * spacing;
    return settings;
}

//! The added mass of a sphere in unbounded ideal fluid is half the water it displaces (Lamb,
//! "Hydrodynamics", 1932, §92). A sphere carries no water along when it turns: no added inertia.
constexpr double kSphereAddedMassShare = 0.5;

} // namespace

RigidCoupling::RigidCoupling(const Vec3d& gravity, double spacing)
    : gravity_(gravity), contacts_(contactSettings(spacing)) {}

void RigidCoupling::sumReactions(const std::vector<RigidBody>& bodies,
                                 const BoundaryModel& boundary,
                                 const std::vector<Vec3d>& reactions) {
    forces_.assign(bodies.size(), Vec3d::Zero());
    torques_.assign(bodies.size(), Vec3d::Zero());
    const BoundaryLayer& layer = boundary.movingLayer();
    const auto& bodyOf = layer.bodyOf();
    for (std::size_t b = 0; b < reactions.size(); ++b) {
        const std::uint32_t body = bodyOf[b];
        if (!bodies[body].isDynamic())
            continue;
        const Vec3d arm = layer.positions()[b].cast<double>() - bodies[body].position();
        forces_[body] += reactions[b];
        torques_[body] += arm.cross(reactions[b]);
    }
}

void RigidCoupling::addBubblesAddedMass(const std::vector<RigidBody>& bodies) {
    // A bubble weighs a tenth of the water it displaces, and a divergence-free step pushes the
    // water around it out of the way within the step: moved on its own mass, a bubble takes in
    // one step the reaction of the water it would have to push, about five times its mass, and
    // overshoots by that much, alternately each way (the added-mass instability of partitioned
    // coupling, Causin, Gerbeau & Nobile 2005, amplification mₐ/m). On m + mₐ the error shrinks by
    // mₐ/(m + mₐ) each step instead. Forces that balance (buoyancy against weight and the drag of
    // eq. 6 at the rise speed) balance as before: only how fast a bubble answers a change differs,
    // as a real bubble's does (Magnaudet & Eames 2000).
    for (std::size_t k = bubblesFrom_; k < bodies.size(); ++k) {
        if (!bodies[k].isDynamic())
            continue;
        const double mass = 1.0 / bodies[k].inertia().inverseMass();
        const double addedMass = kSphereAddedMassShare * bubbleWaterDensity_ * bodies[k].volume();
        const double share = mass / (mass + addedMass);
        forces_[k] = share * (forces_[k] + mass * gravity_) - mass * gravity_;
    }
}

void RigidCoupling::advance(std::vector<RigidBody>& bodies, const BoundaryModel& boundary,
                            const std::vector<Vec3d>& reactions, double dt,
                            const ExtraForces& extraForces) {
    sumReactions(bodies, boundary, reactions);
    const bool bubblesAsSolved = bubbleWaterDensity_ > 0.0 && bubblesFrom_ < bodies.size();
    if (bubblesAsSolved) {
        addBubblesAddedMass(bodies);
        bubbleStartPositions_.clear();
        bubbleStartVelocities_.clear();
        for (std::size_t k = bubblesFrom_; k < bodies.size(); ++k) {
            bubbleStartPositions_.push_back(bodies[k].position());
            bubbleStartVelocities_.push_back(bodies[k].state().linearVelocity);
        }
    }
    // The water's force stays what the step's solve found; the contacts between bodies are
    // resolved at no more than kMaxContactStep each.
    const int substeps = std::max(1, static_cast<int>(std::ceil(dt / kMaxContactStep - 1e-9)));
    const double substep = dt / substeps;
    for (int k = 0; k < substeps; ++k)
        advanceSubstep(bodies, substep, extraForces);
    if (bubblesAsSolved)
        moveBubblesAsSolved(bodies, bubbleStartPositions_, bubbleStartVelocities_, dt);
}

void RigidCoupling::moveBubblesAsSolved(std::vector<RigidBody>& bodies,
                                        const std::vector<Vec3d>& startPositions,
                                        const std::vector<Vec3d>& startVelocities,
                                        double dt) const {
    // The divergence-free step solved the water against each bubble moving at its start
    // velocity (BodySolveCoupling leaves bubbles out). Moved instead with the velocity the
    // water's reaction and eqs. 5–6 give it, a bubble ends the step where the water did not make
    // room for it, and the water next to it starts the next step compressed: measured on the
    // bubble column at 50 000 particles, 5–20 % at the most compressed particle (docs/VALIDATION.md
    // "Water squeezed against bubbles"). So the step's move is the one solved against, and the new
    // velocity moves the bubble from the next step on: a step of lag, the coupling's as before.
    for (std::size_t k = bubblesFrom_; k < bodies.size(); ++k) {
        if (!bodies[k].isDynamic())
            continue;
        RigidBodyState state = bodies[k].state();
        state.position = startPositions[k - bubblesFrom_] + dt * startVelocities[k - bubblesFrom_];
        bodies[k].setState(state);
    }
}

void RigidCoupling::advanceSubstep(std::vector<RigidBody>& bodies, double dt,
                                   const ExtraForces& extraForces) {
    std::vector<Vec3d> turnRates(bodies.size(), Vec3d::Zero());
    std::vector<Vec3d> spinBeforeContacts(bodies.size(), Vec3d::Zero());
    std::vector<Vec3d> velocitiesBefore(extraForces ? bodies.size() : 0, Vec3d::Zero());
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        if (!bodies[k].isDynamic())
            continue;
        RigidBodyState state = bodies[k].state();
        if (extraForces)
            velocitiesBefore[k] = state.linearVelocity;
        turnRates[k] = RigidIntegrator::accelerate(state, bodies[k].inertia(), forces_[k],
                                                   torques_[k], gravity_, dt);
        spinBeforeContacts[k] = state.angularVelocity;
        bodies[k].setState(state);
    }
    if (extraForces)
        extraForces(bodies, velocitiesBefore, dt);
    const std::vector<RigidVelocity> pushes = contacts_.solve(bodies, dt);
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        if (!bodies[k].isDynamic())
            continue;
        RigidBodyState state = bodies[k].state();
        // Contacts change ω after the mean was taken: turn with the mean plus that change.
        const Vec3d turnRate = turnRates[k] + (state.angularVelocity - spinBeforeContacts[k]);
        RigidIntegrator::advancePose(state, turnRate, pushes[k], dt);
        bodies[k].setState(state);
    }
}

} // namespace airtrap
