#include "rigid/RigidImpulse.h"

namespace airtrap {

void RigidImpulse::apply(RigidBodyState& state, const RigidBodyInertia& inertia,
                         const Vec3d& impulse, const Vec3d& contactPoint) {
    if (inertia.isInfinite())
        return;
    const Vec3d r = contactPoint - state.position;
    state.linearVelocity += inertia.inverseMass() * impulse;
    state.angularVelocity += inertia.inverseInertiaWorld(state.orientation) * r.cross(impulse);
}

double RigidImpulse::inverseEffectiveMass(const RigidBodyInertia& inertia, const Quatd& orientation,
                                          const Vec3d& normal, const Vec3d& r) {
    if (inertia.isInfinite())
        return 0.0;
    const Vec3d angular = inertia.inverseInertiaWorld(orientation) * r.cross(normal);
    return inertia.inverseMass() + normal.dot(angular.cross(r));
}

} // namespace airtrap
