// Boundary particles on solid shapes: about one per spacing² of surface, neighbours about a
// spacing apart, every particle on the surface with a unit normal pointing into the water, and
// positive Akinci volumes.
#include "MeshTestSupport.h"
#include "rigid/MeshLoader.h"
#include "rigid/ShapeSampler.h"
#include "rigid/SignedDistanceField.h"
#include "sph/BoundaryVolumes.h"
#include "support/TestMain.h"

#include <QtTest>
#include <functional>
#include <numbers>

using namespace airtrap;
using namespace airtrap::test;

class TestShapeSampling : public QObject {
    Q_OBJECT

    static constexpr double kSpacing = 0.01; // m

    //! The checks every sampling must pass: count near area/spacing², neighbours 0.7–1.3
    //! spacings apart for 95 % of particles, unit normals, positive volumes.
    static void checkSpacingAndVolumes(BoundaryParticles particles, double area, double spacing) {
        const double expected = area / (spacing * spacing);
        qInfo("%zu particles for %.0f spacing² of surface", particles.size(), expected);
        QVERIFY(relativeError(double(particles.size()), expected) < 0.15);
        const std::vector<double> nearest = nearestNeighbourDistances(particles.positions);
        const double regular = fractionWithin(nearest, 0.7 * spacing, 1.3 * spacing);
        qInfo("%.1f %% with a neighbour 0.7–1.3 spacings away", 100 * regular);
        QVERIFY(regular >= 0.95);
        for (const Vec3f& n : particles.normals)
            QVERIFY(std::abs(n.norm() - 1.0f) < 1e-5f);
        BoundaryVolumes::compute(particles, CubicSplineKernel(float(2 * spacing)), spacing);
        for (float volume : particles.volumes)
            QVERIFY(volume > 0.0f);
    }

private Q_SLOTS:
    void sphere() {
        const double r = 0.1;
        const BoundaryParticles particles = ShapeSampler::sampleSphere(r, kSpacing);
        for (std::size_t b = 0; b < particles.size(); ++b) {
            const Vec3d p = particles.positions[b].cast<double>();
            QVERIFY(std::abs(p.norm() - r) < 1e-6);
            QVERIFY(particles.normals[b].cast<double>().dot(p / p.norm()) > 1.0 - 1e-6);
        }
        checkSpacingAndVolumes(particles, 4 * std::numbers::pi * r * r, kSpacing);
    }

    void smallSphere() {
        // A bubble of two spacings' radius: still about one particle per spacing².
        const BoundaryParticles particles = ShapeSampler::sampleSphere(2 * kSpacing, kSpacing);
        QCOMPARE(particles.size(), std::size_t(50)); // round(16π)
        QCOMPARE(ShapeSampler::sampleSphere(0.1 * kSpacing, kSpacing).size(), std::size_t(1));
    }

    void cylinder() {
        const double r = 0.1, h = 0.3;
        const BoundaryParticles particles = ShapeSampler::sampleCylinder(r, h, kSpacing);
        for (std::size_t b = 0; b < particles.size(); ++b) {
            const Vec3d p = particles.positions[b].cast<double>();
            const double radial = std::hypot(p.x(), p.z());
            const bool onSide = std::abs(radial - r) < 1e-6 && std::abs(p.y()) <= 0.5 * h + 1e-6;
            const bool onCap = std::abs(std::abs(p.y()) - 0.5 * h) < 1e-6 && radial <= r + 1e-6;
            QVERIFY(onSide || onCap);
            // Outward: the shape is convex around the origin, so the normal leads away from it.
            const Vec3d n = particles.normals[b].cast<double>();
            QVERIFY(n.dot(p) > 0.0);
            if (onCap && !onSide)
                QVERIFY(std::abs(n.y()) > 1.0 - 1e-6);
            if (onSide && !onCap)
                QVERIFY(std::abs(n.y()) < 1e-6);
        }
        checkSpacingAndVolumes(particles, 2 * std::numbers::pi * r * (r + h), kSpacing);
    }

    void solidBox() {
        const Vec3d size(0.2, 0.1, 0.3);
        const BoundaryParticles particles = ShapeSampler::sampleSolidBox(size, kSpacing);
        for (std::size_t b = 0; b < particles.size(); ++b) {
            const Vec3d p = particles.positions[b].cast<double>();
            const Vec3d gap = (p.cwiseAbs() - 0.5 * size).cwiseAbs();
            QVERIFY(gap.minCoeff() < 1e-6);                                     // on a face
            QVERIFY((p.cwiseAbs().array() <= 0.5 * size.array() + 1e-6).all()); // not beyond
            QVERIFY(particles.normals[b].cast<double>().dot(p) > 0.0);
        }
        const double area = 2 * (size.x() * size.y() + size.y() * size.z() + size.z() * size.x());
        checkSpacingAndVolumes(particles, area, kSpacing);
    }

    void sphereMesh() {
        const double r = 0.1;
        const TriangleMesh mesh = icosphere(r, 4);
        const BoundaryParticles particles = ShapeSampler::sampleMesh(mesh, kSpacing);
        const double voxel = 0.005;
        const SignedDistanceField sdf(mesh, voxel);
        for (std::size_t b = 0; b < particles.size(); ++b) {
            const Vec3d p = particles.positions[b].cast<double>();
            QVERIFY(std::abs(sdf.distance(p)) < 0.5 * voxel);
            // Flat faces of a 5120-face sphere lean at most a couple of degrees from radial.
            QVERIFY(particles.normals[b].cast<double>().dot(p.normalized()) > 0.99);
        }
        checkSpacingAndVolumes(particles, mesh.surfaceArea(), kSpacing);
    }

    void bunnyMesh() {
        const TriangleMesh bunny =
            MeshLoader::load(std::string(AIRTRAP_SOURCE_DIR) + "/tests/data/bunny_lowres.obj");
        const double spacing = 0.004; // the bunny is 15 cm across
        const BoundaryParticles particles = ShapeSampler::sampleMesh(bunny, spacing);
        const double voxel = 0.002;
        const SignedDistanceField sdf(bunny, voxel);
        int alongGradient = 0;
        for (std::size_t b = 0; b < particles.size(); ++b) {
            const Vec3d p = particles.positions[b].cast<double>();
            QVERIFY(std::abs(sdf.distance(p)) < 0.5 * voxel);
            const Vec3d n = particles.normals[b].cast<double>();
            alongGradient += n.dot(sdf.normal(p)) > 0.5 ? 1 : 0;
        }
        // Outward: the triangle normals agree with the field's gradient, except where the ears
        // are thinner than the gradient's stencil of two voxels.
        qInfo("%.2f %% of normals within 60° of the distance gradient",
              100.0 * alongGradient / double(particles.size()));
        QVERIFY(alongGradient >= 0.98 * double(particles.size()));
        checkSpacingAndVolumes(particles, bunny.surfaceArea(), spacing);
    }

    void meshSamplingIsDeterministic() {
        const TriangleMesh mesh = icosphere(0.05, 3);
        const BoundaryParticles first = ShapeSampler::sampleMesh(mesh, kSpacing);
        const BoundaryParticles second = ShapeSampler::sampleMesh(mesh, kSpacing);
        QVERIFY(first.positions == second.positions);
    }
};

AIRTRAP_TEST_APPLESS(TestShapeSampling)
#include "TestShapeSampling.moc"
