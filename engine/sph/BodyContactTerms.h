#pragma once
// What the contact impulse of eq. 4 needs to know about the body a water particle touches,
// gathered once per step: its material, and for a dynamic body the terms of its inverse
// effective mass K(n, r) = 1/M + n · ((I⁻¹ (r × n)) × r); with its velocities and volume, what a
// pressure solve that moves the body needs (BodySolveCoupling).
#include "core/Math.h"

namespace airtrap {

struct BodyContactTerms {
    float restitution = 0.0f;
    float friction = 0.0f;
    bool dynamic = false; //!< whether the impulse moves the body too (K ≠ 0)
    bool bubble = false;  //!< whether the body is a trapped-air bubble's
    Vec3d centre = Vec3d::Zero();
    double inverseMass = 0.0;
    Mat3d inverseInertia = Mat3d::Zero();  //!< world frame
    Vec3d linearVelocity = Vec3d::Zero();  //!< m/s, of `centre`, at the step's start
    Vec3d angularVelocity = Vec3d::Zero(); //!< rad/s, world
    double volume = 0.0;                   //!< m³ (dynamic bodies)

    //! Whether the body is dynamic and at least as dense as water of `restDensity` (kg/m³): one
    //! that can sink onto the floor or another body and close a film of water against it.
    bool sinksIn(double restDensity) const {
        return dynamic && 1.0 / inverseMass >= restDensity * volume;
    }

    //! K(n, r) at world point x along unit `normal`, 1/kg; 0 for a body that cannot move.
    double inverseEffectiveMass(const Vec3d& x, const Vec3d& normal) const {
        if (!dynamic)
            return 0.0;
        const Vec3d r = x - centre;
        return inverseMass + normal.dot((inverseInertia * r.cross(normal)).cross(r));
    }
};

} // namespace airtrap
