#pragma once
// Impulses on a rigid body: the response used by the impulse-based boundary force (IBF,
// docs/METHOD.md "Impulse-based boundary force") for water–body and body–body contacts.
#include "rigid/RigidBodyInertia.h"
#include "rigid/RigidBodyState.h"

namespace airtrap {

class RigidImpulse {
public:
    //! Applies impulse `impulse` (N·s, world) at world point `contactPoint` (m):
    //! ΔV = J/M, Δω = I⁻¹ (r × J) with r = contactPoint − X and I⁻¹ the world inverse inertia
    //! (Mirtich, "Impulse-based Dynamic Simulation of Rigid Body Systems", PhD thesis,
    //! UC Berkeley 1996). No effect on an infinite-mass body.
    static void apply(RigidBodyState& state, const RigidBodyInertia& inertia, const Vec3d& impulse,
                      const Vec3d& contactPoint);

    //! The body's part of the contact denominator, K(n, r) = 1/M + n · ((I⁻¹ (r × n)) × r)
    //! (1/kg): the change of the contact point's velocity along `normal` per unit impulse along
    //! `normal` at offset `r` = contact point − X (m, world). The IBF impulse is
    //! j = −(1 + ε) u_n / (1/m_i + K_B(n, r)), with both bodies' K for a rigid–rigid contact.
    //! 0 for an infinite-mass body. `normal` is expected to be unit length.
    static double inverseEffectiveMass(const RigidBodyInertia& inertia, const Quatd& orientation,
                                       const Vec3d& normal, const Vec3d& r);
};

} // namespace airtrap
