#pragma once
// Mass, centre of mass and inertia tensor of a solid of uniform density: what a dynamic rigid body
// needs for the impulse of docs/METHOD.md "Impulse-based boundary force" (1/M and I⁻¹ in the
// denominator of j).
#include "core/Math.h"

namespace airtrap {

struct TriangleMesh;

struct MassProperties {
    double mass = 0.0;                  //!< kg
    double volume = 0.0;                //!< m³
    Vec3d centreOfMass = Vec3d::Zero(); //!< m, in the shape's own frame
    Mat3d inertia = Mat3d::Zero();      //!< kg·m², about the centre of mass, shape's axes

    //! Solid box of edge lengths `size` (m), centred at the origin; `density` in kg/m³.
    static MassProperties ofBox(const Vec3d& size, double density);
    //! Solid sphere of `radius` (m) centred at the origin.
    static MassProperties ofSphere(double radius, double density);
    //! Solid cylinder of `radius` and `height` (m) along the local y axis, centred at the origin.
    static MassProperties ofCylinder(double radius, double height, double density);
    //! The solid bounded by a closed, outward-facing `mesh` (as MeshLoader::load returns it),
    //! integrated exactly over its triangles.
    //! @throw Error (InvalidInput) if the mesh encloses no positive volume.
    static MassProperties ofMesh(const TriangleMesh& mesh, double density);

private:
    //! A body with the given volume and inertia per unit density, centred at the origin.
    static MassProperties centred(double volume, const Vec3d& principalInertiaPerDensity,
                                  double density);
};

} // namespace airtrap
