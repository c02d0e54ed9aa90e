#pragma once
// Mass and inertia of a rigid body: fixed for a bake, so not part of the cached RigidBodyState.
#include "core/Math.h"

namespace airtrap {

//! Mass and body-frame inertia tensor about the centre of mass. Static and kinematic bodies use
//! infinite(): infinite mass and inertia, zero inverses, so they take no part in an impulse's
//! response (their term in the contact denominator is 0, docs/METHOD.md "Impulse-based boundary
//! force").
class RigidBodyInertia {
public:
    //! `mass` in kg (finite, > 0); `inertiaBody` in kg·m² about the centre of mass in the body
    //! frame, symmetric positive definite (not necessarily diagonal). Throws
    //! Error(InvalidInput) otherwise. From a shape: RigidBodyInertia(p.mass, p.inertia) with
    //! p = MassProperties::ofSphere(...), ofBox(...) or ofMesh(...).
    RigidBodyInertia(double mass, const Mat3d& inertiaBody);

    //! A body that forces and impulses cannot move.
    static RigidBodyInertia infinite();

    bool isInfinite() const { return inverseMass_ == 0.0; }
    double mass() const { return mass_; }                     //!< kg; +inf when infinite
    double inverseMass() const { return inverseMass_; }       //!< 1/kg; 0 when infinite
    const Mat3d& inertiaBody() const { return inertiaBody_; } //!< kg·m²; +inf diagonal if infinite
    const Mat3d& inverseInertiaBody() const { return inverseInertiaBody_; } //!< 1/(kg·m²)

    //! World-frame inverse inertia for a body at `orientation`: I⁻¹ = R I_body⁻¹ Rᵀ
    //! (docs/METHOD.md "Impulse-based boundary force"; Baraff, "Rigid Body Simulation",
    //! SIGGRAPH 2001 course notes).
    Mat3d inverseInertiaWorld(const Quatd& orientation) const;
    //! World-frame inertia R I_body Rᵀ (kg·m²), for angular momentum L = I ω; finite bodies only.
    Mat3d inertiaWorld(const Quatd& orientation) const;

private:
    RigidBodyInertia() = default;

    double mass_ = 0.0;
    double inverseMass_ = 0.0;
    Mat3d inertiaBody_ = Mat3d::Zero();
    Mat3d inverseInertiaBody_ = Mat3d::Zero();
};

} // namespace airtrap
