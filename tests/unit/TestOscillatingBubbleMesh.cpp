// The oscillating bubble mesh of paper §4.1 (eqs. 7–10): its volume is the simulated sphere's at
// every moment, exactly (the tessellation's shortfall is made up); its distinct axis follows the
// velocity; the wobble stays within k·r and dies out after T, leaving a sphere.
#include "post/Icosphere.h"
#include "post/OscillatingBubbleMesh.h"
#include "support/TestMain.h"

#include <Eigen/Eigenvalues>
#include <QtTest>
#include <cmath>

using namespace airtrap;

namespace {

BubbleState bubbleAt(const Vec3d& centre, double radius, const Vec3d& velocity, double age) {
    BubbleState bubble;
    bubble.radius = radius;
    bubble.body.position = centre;
    bubble.body.linearVelocity = velocity;
    bubble.age = age;
    return bubble;
}

//! The unit eigenvector of the vertices' second moment about `centre` whose eigenvalue stands
//! apart from the other two (the icosphere's vertices have an isotropic second moment, so the
//! moment's axes are the ellipsoid's).
Vec3d distinctAxis(const TriangleMesh& mesh, const Vec3d& centre) {
    Eigen::Matrix3d moment = Eigen::Matrix3d::Zero();
    for (const Vec3d& v : mesh.vertices)
        moment += (v - centre) * (v - centre).transpose();
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(moment);
    const Eigen::Vector3d values = solver.eigenvalues(); // ascending
    const int distinct = (values[1] - values[0] > values[2] - values[1]) ? 0 : 2;
    return solver.eigenvectors().col(distinct);
}

} // namespace

class TestOscillatingBubbleMesh : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void icosphereIsClosedAndApproachesTheSphere() {
        double previousError = 3.0; // each level should cut the error about fourfold (∝ edge²)
        for (int level = 0; level <= 4; ++level) {
            const TriangleMesh sphere = unitIcosphere(level);
            QCOMPARE(sphere.triangleCount(), std::size_t(20) << (2 * level));
            const TriangleMesh::EdgeCounts edges = sphere.countEdges();
            QCOMPARE(edges.open + edges.nonManifold + edges.misoriented, std::size_t(0));
            const double error = 1.0 - sphere.signedVolume() / (4.0 / 3.0 * kPi);
            qInfo("level %d: %zu triangles, volume %.3f %% under the sphere's", level,
                  sphere.triangleCount(), 100.0 * error);
            QVERIFY(error > 0.0 && error < previousError / 3.0);
            previousError = error;
        }
        QVERIFY(previousError < 0.003);
        QVERIFY_THROWS_EXCEPTION(std::exception, unitIcosphere(7));
    }

    void volumeIsTheSpheresAtEveryMoment() {
        BubbleMeshSettings settings;
        settings.magnitude = 0.2;
        const OscillatingBubbleMesh shapes(settings);
        const double radius = 0.013;
        double largestWobble = 0.0;
        for (int sample = 0; sample <= 200; ++sample) {
            const double age = 0.6 * settings.duration * sample / 100.0;
            const BubbleState bubble =
                bubbleAt(Vec3d(0.3, 0.1, -0.2), radius, Vec3d(0.1, 0.2, -0.05), age);
            const TriangleMesh mesh = shapes.build(bubble);
            const double volume =
                mesh.signedVolume() / (4.0 / 3.0 * kPi * radius * radius * radius);
            QVERIFY2(std::abs(volume - 1.0) < 1e-9,
                     qPrintable(QString("t = %1 s: volume ratio %2").arg(age).arg(volume)));
            const double wobble = shapes.deformation(radius, age);
            QVERIFY(std::abs(wobble) <= settings.magnitude * radius);
            largestWobble = std::max(largestWobble, std::abs(wobble));
        }
        // It does wobble: the decaying sine's first crest reaches most of k·r.
        QVERIFY(largestWobble > 0.6 * settings.magnitude * radius);
    }

    void distinctAxisFollowsTheVelocity_data() {
        QTest::addColumn<double>("vx");
        QTest::addColumn<double>("vy");
        QTest::addColumn<double>("vz");
        QTest::newRow("rising") << 0.0 << 0.25 << 0.0;
        QTest::newRow("oblique") << 0.3 << -0.1 << 0.2;
        QTest::newRow("along -z") << 0.0 << 0.0 << -0.4;
    }

    void distinctAxisFollowsTheVelocity() {
        QFETCH(double, vx);
        QFETCH(double, vy);
        QFETCH(double, vz);
        const Vec3d velocity(vx, vy, vz);
        const BubbleMeshSettings settings;
        const OscillatingBubbleMesh shapes(settings);
        // A quarter cycle before the first trough of the sine: δ < 0, so the bubble is narrower
        // across and longer along its path.
        const double age = settings.duration * 0.75 / settings.cycles;
        const double radius = 0.01;
        QVERIFY(shapes.deformation(radius, age) < 0.0);
        const Vec3d axes = shapes.semiAxes(radius, age);
        QVERIFY(axes.z() > radius && axes.x() < radius);
        const Vec3d centre(0.5, 0.2, 0.1);
        const TriangleMesh mesh = shapes.build(bubbleAt(centre, radius, velocity, age));
        const double cosine = std::abs(distinctAxis(mesh, centre).dot(velocity.normalized()));
        QVERIFY2(cosine > std::cos(kPi / 180.0), qPrintable(QString("cos %1").arg(cosine)));
        double longest = 0.0;
        for (const Vec3d& v : mesh.vertices)
            longest = std::max(longest, (v - centre).norm());
        // The mesh is grown by the tessellation's volume shortfall (about 1.1 % in radius).
        QVERIFY(longest <= axes.z() * 1.012 && longest > radius);
    }

    void aBubbleAtRestOrPastItsWobbleIsASphere() {
        const BubbleMeshSettings settings;
        const OscillatingBubbleMesh shapes(settings);
        const double radius = 0.02;
        for (double age : {0.0, settings.duration * 1.01, 3.0}) {
            QCOMPARE(shapes.deformation(radius, age), 0.0);
            const Vec3d axes = shapes.semiAxes(radius, age);
            QVERIFY((axes - Vec3d::Constant(radius)).norm() < 1e-15);
        }
        QVERIFY(OscillatingBubbleMesh::alignment(Vec3d::Zero()).isApprox(Quatd::Identity()));
        const TriangleMesh mesh = shapes.build(bubbleAt(Vec3d::Zero(), radius, Vec3d::Zero(), 0.1));
        QVERIFY(mesh.signedVolume() > 0.0);
    }
};

AIRTRAP_TEST_APPLESS(TestOscillatingBubbleMesh)
#include "TestOscillatingBubbleMesh.moc"
