#pragma once
// One layer of boundary particles on the surface of a solid body (a dynamic object, a bubble, an
// obstacle), in the body's frame with the water outside (Akinci et al. 2012: one layer suffices,
// sampling may be non-uniform). The particles sit exactly on the surface; a caller that wants
// them inset moves them along their normals. Volumes are left at zero: fill them with
// BoundaryVolumes::compute(particles, kernel, waterSpacing).
#include "rigid/BoundaryParticles.h"

namespace airtrap {

struct TriangleMesh;

class ShapeSampler {
public:
    //! Sphere of `radius` (m) centred at the origin: a Fibonacci spiral of about 4πr²/spacing²
    //! points (at least one), so each stands for spacing² of surface; normals radial.
    static BoundaryParticles sampleSphere(double radius, double spacing);

    //! Cylinder of `radius` and `height` (m) along y, centred at the origin: rings about
    //! `spacing` apart on the side and concentric rings on both caps. Normals are radial on the
    //! side, ±y on the caps and the normalised sum of both on the rims.
    static BoundaryParticles sampleCylinder(double radius, double height, double spacing);

    //! All six faces of a box of edge lengths `size` (m) centred at the origin, water outside
    //! (BoundarySampler::sampleBox on a lattice of about `spacing`).
    static BoundaryParticles sampleSolidBox(const Vec3d& size, double spacing);

    //! The surface of a closed, outward-facing `mesh`: no two points closer than 0.8·spacing,
    //! neighbours about `spacing` apart, about area/spacing² of them, each with its triangle's
    //! normal.
    //! Deterministic: the same mesh and spacing give the same particles.
    static BoundaryParticles sampleMesh(const TriangleMesh& mesh, double spacing);

private:
    static void requirePositive(double value, const char* what);
    static void append(BoundaryParticles& out, const Vec3d& position, const Vec3d& normal);
    //! A ring of points about `spacing` apart at `ringRadius` around the y axis, height `y`,
    //! shifted by `phase` of a step; normal ∝ radialWeight · radial + axialNormal.
    static void appendRing(BoundaryParticles& out, double ringRadius, double y, double spacing,
                           double phase, double radialWeight, const Vec3d& axialNormal);
};

} // namespace airtrap
