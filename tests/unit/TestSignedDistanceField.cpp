// Signed distance field of a mesh: distances against a sphere's, outward normals, inside tests
// from the surface to the deep interior of a large body, and concurrent reads.
#include "MeshTestSupport.h"
#include "core/Error.h"
#include "rigid/SignedDistanceField.h"
#include "support/TestMain.h"

#include <QtTest>
#include <tbb/parallel_for.h>

using namespace airtrap;
using namespace airtrap::test;

class TestSignedDistanceField : public QObject {
    Q_OBJECT

    static constexpr double kRadius = 0.1;  // m
    static constexpr double kVoxel = 0.005; // m, 20 voxels per radius

    //! Directions spread over the sphere (a Fibonacci spiral), for probing all around.
    static std::vector<Vec3d> directions(int count) {
        std::vector<Vec3d> out;
        for (int i = 0; i < count; ++i) {
            const double y = 1.0 - (2.0 * i + 1.0) / count;
            const double ring = std::sqrt(1.0 - y * y);
            const double angle = 2.399963229728653 * i; // golden angle
            out.emplace_back(ring * std::cos(angle), y, ring * std::sin(angle));
        }
        return out;
    }

private Q_SLOTS:
    void sphereDistances() {
        // Exterior band of 25 voxels so that 2r (20 voxels out) still holds a true distance.
        const SignedDistanceField sdf(icosphere(kRadius, 4), kVoxel, 25.0);
        QVERIFY(std::abs(sdf.distance(Vec3d::Zero()) + kRadius) < kVoxel);
        for (const Vec3d& direction : directions(50)) {
            QVERIFY(std::abs(sdf.distance(2.0 * kRadius * direction) - kRadius) < kVoxel);
            QVERIFY(std::abs(sdf.distance(kRadius * direction)) < 0.5 * kVoxel);
            QVERIFY(std::abs(sdf.distance(0.5 * kRadius * direction) + 0.5 * kRadius) < kVoxel);
        }
        // Beyond the band the field is flat at the band's width.
        QCOMPARE(sdf.exteriorBand(), 25.0 * kVoxel);
        QCOMPARE(sdf.distance(Vec3d(10.0, 0.0, 0.0)), sdf.exteriorBand());
    }

    void normalsPointOutward() {
        const SignedDistanceField sdf(icosphere(kRadius, 4), kVoxel);
        for (const Vec3d& direction : directions(200))
            for (const double depth : {-0.5 * kVoxel, 0.0, 0.5 * kVoxel}) {
                const Vec3d n = sdf.normal((kRadius + depth) * direction);
                QVERIFY(std::abs(n.norm() - 1.0) < 1e-9);
                QVERIFY2(n.dot(direction) > 0.99, qPrintable(QString::number(n.dot(direction))));
            }
        QCOMPARE(sdf.normal(Vec3d(10.0, 0.0, 0.0)), Vec3d::Zero()); // flat far outside
    }

    void insideTests() {
        const SignedDistanceField sdf(icosphere(kRadius, 4), kVoxel);
        QVERIFY(sdf.isInside(Vec3d::Zero()));
        for (const Vec3d& direction : directions(100)) {
            QVERIFY(sdf.isInside((kRadius - kVoxel) * direction));
            QVERIFY(!sdf.isInside((kRadius + kVoxel) * direction));
            QVERIFY(!sdf.isInside(10.0 * kRadius * direction));
        }
    }

    void boundsHoldTheSurfaceAndItsBand() {
        const SignedDistanceField sdf(icosphere(kRadius, 4), kVoxel);
        const Aabb bounds = sdf.bounds();
        QVERIFY((bounds.min.array() < -kRadius).all() && (bounds.max.array() > kRadius).all());
        // No more than the band and a leaf of voxels beyond it.
        QVERIFY((bounds.max.array() < kRadius + 12 * kVoxel).all());
    }

    void deepInsideALargeBody() {
        // A 1 m cube at 2 cm voxels: its centre is 25 voxels from the surface.
        const TriangleMesh box = cube(1.0);
        const SignedDistanceField filled(box, 0.02);
        QVERIFY(filled.isInside(Vec3d::Zero()));
        QVERIFY(std::abs(filled.distance(Vec3d::Zero()) + 0.5) < 0.02);
        QVERIFY(filled.isInside(Vec3d(0.49, -0.49, 0.3)));
        QVERIFY(!filled.isInside(Vec3d(0.51, 0.0, 0.0)));
        // With a narrow interior band the sign is still flood-filled into the interior; only the
        // distance stops at the band.
        const SignedDistanceField narrow(box, 0.02, 3.0, 3.0);
        QVERIFY(narrow.isInside(Vec3d::Zero()));
        QVERIFY(narrow.isInside(Vec3d(0.2, 0.1, -0.3)));
        QVERIFY(std::abs(narrow.distance(Vec3d::Zero()) + 3 * 0.02) < 1e-6);
        QVERIFY(!narrow.isInside(Vec3d(0.0, 0.7, 0.0)));
    }

    void smallBodyInside() {
        // A 10 cm cube at 2 mm voxels.
        const SignedDistanceField sdf(cube(0.1), 0.002);
        QVERIFY(sdf.isInside(Vec3d::Zero()));
        QVERIFY(std::abs(sdf.distance(Vec3d::Zero()) + 0.05) < 0.002);
        QVERIFY(std::abs(sdf.distance(Vec3d(0.05, 0.01, 0.0))) < 0.001);
    }

    void concurrentReadsAgreeWithSerialOnes() {
        const SignedDistanceField sdf(icosphere(kRadius, 4), kVoxel);
        const std::vector<Vec3d> probes = [] {
            std::vector<Vec3d> out;
            for (const Vec3d& d : directions(20000))
                out.push_back(kRadius * (0.8 + 0.4 * std::abs(d.x())) * d);
            return out;
        }();
        std::vector<double> serial(probes.size()), parallel(probes.size());
        for (std::size_t i = 0; i < probes.size(); ++i)
            serial[i] = sdf.distance(probes[i]);
        tbb::parallel_for(std::size_t(0), probes.size(),
                          [&](std::size_t i) { parallel[i] = sdf.distance(probes[i]); });
        QVERIFY(serial == parallel);
    }

    void refusesBadInput() {
        QVERIFY_THROWS_EXCEPTION(Error, SignedDistanceField(cube(1.0), 0.0));
        QVERIFY_THROWS_EXCEPTION(Error, SignedDistanceField(TriangleMesh{}, 0.01));
    }
};

AIRTRAP_TEST_APPLESS(TestSignedDistanceField)
#include "TestSignedDistanceField.moc"
