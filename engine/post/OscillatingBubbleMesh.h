#pragma once
// The shape a bubble is rendered with (paper §4.1): an ellipsoid whose distinct axis follows the
// bubble's velocity and whose cross radius wobbles and dies away after the bubble's birth, while
// its volume stays that of the simulated sphere, so the look is soft without a soft body.
//   α(t) = β(t) = r + δ(t)                                   (eqs. 7, 8)
//   γ(t) = 3V / (4π α β) = r³ / α²     (V = 4/3 π r³)          (eq. 9)
//   δ(t) = k r (t/T − 1)² sin(2nπ t/T) for 0 < t ≤ T, else 0 (eq. 10)
// γ lies along the velocity: a bubble narrower than r across is stretched along its path.
#include "bubbles/BubbleState.h"
#include "rigid/TriangleMesh.h"
#include "scene/Scene.h"

namespace airtrap {

class OscillatingBubbleMesh {
public:
    explicit OscillatingBubbleMesh(const BubbleMeshSettings& settings);

    //! δ of eq. 10 for a bubble of `radius`, `age` seconds after its birth.
    double deformation(double radius, double age) const;
    //! (α, β, γ) of eqs. 7–9; γ is the semi-axis along the velocity.
    Vec3d semiAxes(double radius, double age) const;
    //! The rotation taking the z axis onto the velocity's direction (none for a bubble at rest):
    //! the paper's R, which maps the velocity onto z, is its inverse.
    static Quatd alignment(const Vec3d& velocity);
    //! The bubble's closed mesh in world space, counter-clockwise seen from outside, enclosing
    //! 4/3·π·r³ exactly (its vertices lie just outside the ellipsoid, by the tessellation's
    //! shortfall).
    TriangleMesh build(const BubbleState& bubble) const;
    std::size_t triangleCount() const { return unitSphere_.triangleCount(); }

private:
    BubbleMeshSettings settings_;
    TriangleMesh unitSphere_;
};

} // namespace airtrap
