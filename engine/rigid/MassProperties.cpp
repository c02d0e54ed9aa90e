#include "rigid/MassProperties.h"

#include "core/Error.h"
#include "rigid/TriangleMesh.h"

#include <cmath>
#include <numbers>
#include <string>

namespace airtrap {

namespace {

void requirePositive(double value, const char* what) {
    if (!std::isfinite(value) || value <= 0.0)
        throw Error(ErrorKind::InvalidInput,
                    std::string(what) + " must be a positive number, got " + std::to_string(value));
}

//! ∫ u uᵀ dV over the unit tetrahedron with corners 0, e₁, e₂, e₃: 1/60 on the diagonal and
//! 1/120 off it (Tonon 2005, "Explicit exact formulas for the 3-D tetrahedron inertia tensor in
//! terms of its vertex coordinates", J. Math. Stat. 1(1); Blow & Binstock 2004, "How to find the
//! inertia tensor (or other mass properties) of a 3D solid body represented by a triangle mesh").
Mat3d unitTetrahedronSecondMoment() {
    Mat3d moment = Mat3d::Constant(1.0 / 120.0);
    moment.diagonal().setConstant(2.0 / 120.0);
    return moment;
}

} // namespace

MassProperties MassProperties::centred(double volume, const Vec3d& principalInertiaPerDensity,
                                       double density) {
    requirePositive(density, "density");
    MassProperties out;
    out.volume = volume;
    out.mass = density * volume;
    out.inertia = (density * principalInertiaPerDensity).asDiagonal();
    return out;
}

MassProperties MassProperties::ofBox(const Vec3d& size, double density) {
    for (int axis = 0; axis < 3; ++axis)
        requirePositive(size[axis], "box size");
    // I_xx = m (b² + c²)/12 and cyclic, per unit density m = abc.
    const double volume = size.prod();
    const Vec3d squared = size.cwiseAbs2();
    const Vec3d perDensity =
        volume / 12.0 *
        Vec3d(squared.y() + squared.z(), squared.x() + squared.z(), squared.x() + squared.y());
    return centred(volume, perDensity, density);
}

MassProperties MassProperties::ofSphere(double radius, double density) {
    requirePositive(radius, "sphere radius");
    const double volume = 4.0 / 3.0 * std::numbers::pi * radius * radius * radius;
    return centred(volume, Vec3d::Constant(0.4 * volume * radius * radius), density); // 2/5 m r²
}

MassProperties MassProperties::ofCylinder(double radius, double height, double density) {
    requirePositive(radius, "cylinder radius");
    requirePositive(height, "cylinder height");
    const double volume = std::numbers::pi * radius * radius * height;
    // About the axis m r²/2; across it m (3r² + h²)/12.
    const double across = volume * (3.0 * radius * radius + height * height) / 12.0;
    const double along = 0.5 * volume * radius * radius;
    return centred(volume, Vec3d(across, along, across), density);
}

MassProperties MassProperties::ofMesh(const TriangleMesh& mesh, double density) {
    requirePositive(density, "density");
    // Divergence theorem: the solid is the signed sum of the tetrahedra (reference, a, b, c) over
    // its triangles. A tetrahedron with edge vectors A = [a b c] has volume det A / 6, first
    // moment det A/6 · (a + b + c)/4 and second moment ∫ x xᵀ dV = det A · A S Aᵀ, S the unit
    // tetrahedron's. The reference is the box centre so a mesh far from the origin loses no
    // digits to cancellation.
    const Vec3d reference = mesh.bounds().center();
    const Mat3d unitMoment = unitTetrahedronSecondMoment();
    double volume = 0.0;
    Vec3d firstMoment = Vec3d::Zero();
    Mat3d secondMoment = Mat3d::Zero();
    for (const TriangleMesh::Triangle& tri : mesh.triangles) {
        Mat3d edges;
        for (int corner = 0; corner < 3; ++corner)
            edges.col(corner) = mesh.vertices[tri[corner]] - reference;
        const double determinant = edges.determinant();
        volume += determinant / 6.0;
        firstMoment += determinant / 24.0 * edges.rowwise().sum();
        secondMoment += determinant * edges * unitMoment * edges.transpose();
    }
    if (!(volume > 0.0))
        throw Error(ErrorKind::InvalidInput, "mesh encloses no positive volume (" +
                                                 std::to_string(volume) +
                                                 " m³): it must be closed and face outward");

    const Vec3d centre = firstMoment / volume; // relative to the reference
    // Parallel-axis theorem for second moments: about the centre of mass, ∫ x xᵀ loses V c cᵀ.
    const Mat3d centralMoment = secondMoment - volume * centre * centre.transpose();
    MassProperties out;
    out.volume = volume;
    out.mass = density * volume;
    out.centreOfMass = reference + centre;
    // Inertia from the second moment: I = tr(C) 1 − C (e.g. I_xx = ∫ y² + z²).
    out.inertia = density * (centralMoment.trace() * Mat3d::Identity() - centralMoment);
    return out;
}

} // namespace airtrap
