#include "bubbles/BubblePairImpulse.h"

#include "core/Error.h"
#include "rigid/RigidImpulse.h"

namespace airtrap {
namespace {

//! Spheres touch within this share of the sum of their radii (floating-point slack).
constexpr double kTouchTolerance = 1e-9;

void requireNonPositive(double restitution, const char* name) {
    if (!(restitution >= -1.0 && restitution <= 0.0))
        throw Error(ErrorKind::InvalidInput, std::string("bubble restitution ") + name + " = " +
                                                 std::to_string(restitution) +
                                                 " must lie in [-1, 0]");
}

} // namespace

BubblePairImpulse::BubblePairImpulse(double approaching, double overlapping)
    : approaching_(approaching), overlapping_(overlapping) {
    requireNonPositive(approaching, "ε₁ (approaching)");
    requireNonPositive(overlapping, "ε₂ (overlapping)");
}

double BubblePairImpulse::apply(RigidBodyState& a, const RigidBodyInertia& inertiaA, double ra,
                                RigidBodyState& b, const RigidBodyInertia& inertiaB,
                                double rb) const {
    const Vec3d offset = a.position - b.position;
    const double distance = offset.norm();
    const double reach = ra + rb;
    if (distance >= reach * (1.0 + kTouchTolerance) || distance == 0.0)
        return 0.0;
    const Vec3d normal = offset / distance; // from b towards a
    // Spheres: the contact point lies on the line of centres, so the impulse has no torque and
    // only the centres' velocities matter.
    const double approach = (a.linearVelocity - b.linearVelocity).dot(normal);
    if (approach >= 0.0)
        return 0.0;
    const bool overlapping = distance < reach * (1.0 - kTouchTolerance);
    const double restitution = overlapping ? overlapping_ : approaching_;
    const Vec3d point = b.position + (rb / reach) * offset;
    const double inverseMass =
        RigidImpulse::inverseEffectiveMass(inertiaA, a.orientation, normal, point - a.position) +
        RigidImpulse::inverseEffectiveMass(inertiaB, b.orientation, normal, point - b.position);
    if (inverseMass == 0.0)
        return 0.0;
    const double j = -(1.0 + restitution) * approach / inverseMass;
    if (j == 0.0)
        return 0.0;
    RigidImpulse::apply(a, inertiaA, j * normal, point);
    RigidImpulse::apply(b, inertiaB, -j * normal, point);
    return j;
}

} // namespace airtrap
