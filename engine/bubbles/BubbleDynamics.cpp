#include "bubbles/BubbleDynamics.h"

#include "core/Parallel.h"
#include "core/PeriodicEvent.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace airtrap {
namespace {

float square(float x) {
    return x * x;
}

} // namespace

BubbleDynamics::BubbleDynamics(const BubbleSettings& bubbles, const SolverSettings& solver,
                               const CubicSplineKernel& kernel)
    : settings_(bubbles), restDensity_(solver.restDensity), spacing_(solver.particleSpacing),
      support_(kernel.supportRadius()), gravity_(solver.gravity), kernel_(kernel),
      immersion_(solver.particleSpacing), factory_(bubbles, solver, kernel),
      pairs_(bubbles.approachRestitution, bubbles.overlapRestitution) {}

void BubbleDynamics::syncBodies(std::vector<RigidBody>& bodies, std::size_t first,
                                const std::vector<BubbleState>& bubbles) {
    if (sameBubbles(bubbles)) { // most steps: only the states moved on
        for (std::size_t k = 0; k < bubbles.size(); ++k)
            bodies[first + k].setState(bubbles[k].body);
        return;
    }
    std::vector<RigidBody> kept;
    kept.reserve(bubbles.size());
    std::size_t old = 0;
    // Both lists are in creation order (ids increase), so one merge pass finds the kept bodies.
    for (const BubbleState& bubble : bubbles) {
        while (old < bodyIds_.size() && bodyIds_[old] < bubble.id)
            ++old;
        if (old < bodyIds_.size() && bodyIds_[old] == bubble.id) {
            kept.push_back(std::move(bodies[first + old]));
            kept.back().setState(bubble.body);
        } else {
            kept.push_back(factory_.build(bubble));
        }
    }
    bodies.erase(bodies.begin() + static_cast<std::ptrdiff_t>(first), bodies.end());
    std::move(kept.begin(), kept.end(), std::back_inserter(bodies));
    bodyIds_.clear();
    radii_.clear();
    for (const BubbleState& bubble : bubbles) {
        bodyIds_.push_back(bubble.id);
        radii_.push_back(bubble.radius);
    }
}

bool BubbleDynamics::sameBubbles(const std::vector<BubbleState>& bubbles) const {
    if (bubbles.size() != bodyIds_.size())
        return false;
    for (std::size_t k = 0; k < bubbles.size(); ++k)
        if (bubbles[k].id != bodyIds_[k])
            return false;
    return true;
}

double BubbleDynamics::riseSpeed(double radius) const {
    const double stokes =
        2.0 / 9.0 * gravity_.norm() * radius * radius / settings_.kinematicViscosity;
    return std::min(stokes, settings_.maxRiseSpeed);
}

bool BubbleDynamics::measureDue(double from, double to, const std::vector<BubbleState>& bubbles) {
    if (bubbles.empty())
        return false;
    return periodDue(from, to, kMeasureInterval) ||
           std::any_of(bubbles.begin(), bubbles.end(),
                       [](const BubbleState& bubble) { return !bubble.surroundings.measured; });
}

void BubbleDynamics::measureSurroundings(double from, double to,
                                         const std::vector<RigidBody>& bodies, std::size_t first,
                                         std::vector<BubbleState>& bubbles,
                                         const ParticleSet& fluid, const PositionArrays& positions,
                                         const NeighborGrid& grid) const {
    const bool everyBubble = periodDue(from, to, kMeasureInterval);
    // Each bubble writes only its own entry: parallel, and the same bits on any thread count.
    parallelFor(std::size_t(0), bubbles.size(), [&](std::size_t k) {
        BubbleSurroundings& around = bubbles[k].surroundings;
        if (everyBubble || !around.measured)
            around = measureOne(bodies[first + k], radii_[k], fluid, positions, grid);
    });
}

BubbleSurroundings BubbleDynamics::measureOne(const RigidBody& body, double radius,
                                              const ParticleSet& fluid,
                                              const PositionArrays& positions,
                                              const NeighborGrid& grid) const {
    const Vec3d centre = body.position();
    // The water touching a bubble is dragged along with it; the ambient flow is read one
    // support radius further out, beyond the layer the bubble carries. The shells are compared
    // as squared distances from the centre: only the few touching particles need a square root.
    const float outer2 = square(float(radius + 2.0 * support_));
    const float ambient2 = square(float(radius + support_));
    const float touching2 = square(float(immersion_.reach(radius)));
    const Vec3f c = centre.cast<float>();
    const float* px = positions.x.data();
    const float* py = positions.y.data();
    const float* pz = positions.z.data();
    BubbleImmersion::WetProbes wet;
    std::size_t ambientCount = 0;
    Vec3d ambientSum = Vec3d::Zero();
    BubbleSurroundings result;
    result.measured = true;
    grid.forEachRangeInBall(
        centre, radius + 2.0 * support_, [&](std::uint32_t begin, std::uint32_t end) {
            // Branch-free over the shell, which holds about half of the candidates in no
            // predictable order; touching water is rare and takes the branch.
            Vec3f rowSum = Vec3f::Zero();
            float rowCount = 0.0f;
            for (std::uint32_t s = begin; s < end; ++s) {
                const float d2 =
                    square(px[s] - c.x()) + square(py[s] - c.y()) + square(pz[s] - c.z());
                const float inShell = ((d2 >= ambient2) & (d2 < outer2)) ? 1.0f : 0.0f;
                rowSum += inShell * fluid.velocities[s];
                rowCount += inShell;
                if (d2 < touching2 && d2 > 0.0f)
                    result.impactSpeed =
                        std::max(result.impactSpeed, touchingWater(body, radius, positions[s],
                                                                   fluid.velocities[s], wet));
            }
            ambientSum += rowSum.cast<double>();
            ambientCount += static_cast<std::size_t>(rowCount);
        });
    result.waterVelocity =
        ambientCount > 0 ? Vec3d(ambientSum / double(ambientCount)) : body.linearVelocity();
    result.wettedShare = double(wet.count()) / double(BubbleImmersion::kProbeCount);
    result.floating = result.placement() == BubbleImmersion::Placement::Floating;
    return result;
}

double BubbleDynamics::touchingWater(const RigidBody& body, double radius, const Vec3f& position,
                                     const Vec3f& velocity, BubbleImmersion::WetProbes& wet) const {
    immersion_.wetBy(body.position(), radius, position.cast<double>(), wet);
    const Vec3d outward = (position.cast<double>() - body.position()).normalized();
    const Vec3d surfacePoint = body.position() + radius * outward;
    return -(velocity.cast<double>() - body.velocityAt(surfacePoint)).dot(outward);
}

void BubbleDynamics::applyForces(std::vector<RigidBody>& bodies, std::size_t first,
                                 const std::vector<BubbleState>& bubbles,
                                 const std::vector<Vec3d>& before, double dt) const {
    const bool steer = gravity_.squaredNorm() > 0.0;
    const Vec3d up = steer ? Vec3d(-gravity_.normalized()) : Vec3d::UnitY();
    for (std::size_t k = 0; k < bodyIds_.size(); ++k) {
        RigidBody& body = bodies[first + k];
        const BubbleSurroundings& around = bubbles.at(k).surroundings;
        RigidBodyState state = body.state();
        const double radius = radii_[k];
        const double stokesDrag = 6.0 * kPi * restDensity_ * settings_.kinematicViscosity * radius;
        // On the immersed part only: the share of the surface in water.
        const double immersed = around.wettedShare;
        const double rate = immersed * (stokesDrag * body.inertia().inverseMass() + settings_.drag);
        // Implicit: v' = v + Δt·rate·(ū − v') stays between v and ū for any step.
        Vec3d velocity =
            (state.linearVelocity + rate * dt * around.waterVelocity) / (1.0 + rate * dt);
        if (steer && immersed > 0.0) {
            const double target = around.waterVelocity.dot(up) + riseSpeed(radius);
            const double relax = immersed * dt / settings_.riseTime;
            // From the sub-step's own start: the bodies' steps are split at
            // RigidCoupling::kMaxContactStep, and relaxing each piece from the whole step's
            // start would steer a long step only as much as its last piece.
            const double startSpeed = before.at(first + k).dot(up);
            const double steered = (startSpeed + relax * target) / (1.0 + relax);
            velocity += (steered - velocity.dot(up)) * up;
        }
        state.linearVelocity = velocity;
        body.setState(state);
    }
}

void BubbleDynamics::applyPairImpulses(std::vector<RigidBody>& bodies, std::size_t first) const {
    const std::size_t count = bodyIds_.size();
    for (std::size_t a = 0; a < count; ++a)
        for (std::size_t b = a + 1; b < count; ++b) {
            RigidBody& bodyA = bodies[first + a];
            RigidBody& bodyB = bodies[first + b];
            const double reach = radii_[a] + radii_[b];
            if ((bodyA.position() - bodyB.position()).squaredNorm() >= reach * reach)
                continue;
            RigidBodyState stateA = bodyA.state();
            RigidBodyState stateB = bodyB.state();
            if (pairs_.apply(stateA, bodyA.inertia(), radii_[a], stateB, bodyB.inertia(),
                             radii_[b]) > 0.0) {
                bodyA.setState(stateA);
                bodyB.setState(stateB);
            }
        }
}

} // namespace airtrap
