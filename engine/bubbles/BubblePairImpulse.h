#pragma once
// The impulse between two bubbles (paper §3.3.2, docs/METHOD.md "Bubble–bubble impulses"): the
// impulse-based contact of any two bodies, j = −(1 + ε) uₙ / (K_A + K_B), with a non-positive
// coefficient of restitution. ε = 0 would stop their approach; −1 < ε < 0 removes only part of it,
// a weak repulsion that lets them overlap; ε = −1 gives exactly no impulse. ε₁ applies to bubbles
// that touch and approach, ε₂ (ε₁ < ε₂ ≤ 0) to bubbles already overlapping, so that merging can be
// sped up or slowed down. No positional correction: bubbles may overlap, their deletion rule
// decides.
#include "rigid/RigidBodyInertia.h"
#include "rigid/RigidBodyState.h"

namespace airtrap {

class BubblePairImpulse {
public:
    //! `approaching` is ε₁, `overlapping` ε₂; both in [−1, 0].
    BubblePairImpulse(double approaching, double overlapping);

    //! Applies the impulse between bubble `a` (radius ra) and bubble `b` (radius rb) to both
    //! states; returns its size j (N·s, ≥ 0: it never pulls them together). Zero when they do
    //! not touch, move apart, or ε = −1.
    double apply(RigidBodyState& a, const RigidBodyInertia& inertiaA, double ra, RigidBodyState& b,
                 const RigidBodyInertia& inertiaB, double rb) const;

private:
    double approaching_;
    double overlapping_;
};

} // namespace airtrap
