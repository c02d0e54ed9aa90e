// Mass properties: the analytic shapes' textbook formulas, and the exact polyhedral integrals
// against them (a box mesh exactly, a sphere mesh up to its tessellation), with offset and
// rotation carried into the centre of mass and the inertia tensor.
#include "MeshTestSupport.h"
#include "core/Error.h"
#include "rigid/MassProperties.h"
#include "rigid/MeshLoader.h"
#include "support/TestMain.h"

#include <Eigen/Eigenvalues>
#include <QTemporaryDir>
#include <QtTest>
#include <numbers>

using namespace airtrap;
using namespace airtrap::test;

class TestMassProperties : public QObject {
    Q_OBJECT

    static constexpr double kDensity = 700.0; // kg/m³, pine
    QTemporaryDir folder_;

    static double matrixError(const Mat3d& value, const Mat3d& expected) {
        return (value - expected).norm() / expected.norm();
    }

    static bool isDiagonal(const Mat3d& m, const Vec3d& diagonal, double tolerance) {
        return matrixError(m, diagonal.asDiagonal().toDenseMatrix()) < tolerance;
    }

    //! The box of edge lengths `size` as a 12-triangle mesh.
    static TriangleMesh boxMesh(const Vec3d& size) {
        TriangleMesh mesh = cube(1.0);
        for (Vec3d& v : mesh.vertices)
            v = v.cwiseProduct(size);
        return mesh;
    }

private Q_SLOTS:
    void initTestCase() { QVERIFY(folder_.isValid()); }

    void box() {
        const Vec3d size(0.2, 0.3, 0.5);
        const MassProperties box = MassProperties::ofBox(size, kDensity);
        const double mass = kDensity * 0.2 * 0.3 * 0.5;
        QVERIFY(relativeError(box.volume, 0.03) < 1e-12);
        QVERIFY(relativeError(box.mass, mass) < 1e-12);
        QCOMPARE(box.centreOfMass, Vec3d::Zero());
        // I = m/12 (b² + c², a² + c², a² + b²)
        const Vec3d expected = mass / 12.0 * Vec3d(0.09 + 0.25, 0.04 + 0.25, 0.04 + 0.09);
        QVERIFY(isDiagonal(box.inertia, expected, 1e-12));
    }

    void sphere() {
        const double r = 0.1;
        const MassProperties sphere = MassProperties::ofSphere(r, kDensity);
        const double volume = 4.0 / 3.0 * std::numbers::pi * r * r * r;
        QVERIFY(relativeError(sphere.volume, volume) < 1e-12);
        QVERIFY(relativeError(sphere.mass, kDensity * volume) < 1e-12);
        QVERIFY(
            isDiagonal(sphere.inertia, Vec3d::Constant(0.4 * kDensity * volume * r * r), 1e-12));
    }

    void cylinder() {
        const double r = 0.1, h = 0.4;
        const MassProperties cylinder = MassProperties::ofCylinder(r, h, kDensity);
        const double mass = kDensity * std::numbers::pi * r * r * h;
        QVERIFY(relativeError(cylinder.mass, mass) < 1e-12);
        // Axis y: m r²/2 about it, m (3r² + h²)/12 across it.
        const double across = mass * (3 * r * r + h * h) / 12.0;
        QVERIFY(isDiagonal(cylinder.inertia, Vec3d(across, 0.5 * mass * r * r, across), 1e-12));
    }

    void refusesNonPositiveSizes() {
        QVERIFY_THROWS_EXCEPTION(Error, MassProperties::ofSphere(-0.1, kDensity));
        QVERIFY_THROWS_EXCEPTION(Error, MassProperties::ofBox(Vec3d(1, 0, 1), kDensity));
        QVERIFY_THROWS_EXCEPTION(Error, MassProperties::ofCylinder(0.1, 0.2, 0.0));
    }

    void boxMeshIsExact() {
        const Vec3d size(0.2, 0.3, 0.5);
        const MassProperties fromMesh = MassProperties::ofMesh(boxMesh(size), kDensity);
        const MassProperties analytic = MassProperties::ofBox(size, kDensity);
        QVERIFY(relativeError(fromMesh.volume, analytic.volume) < 1e-9);
        QVERIFY(relativeError(fromMesh.mass, analytic.mass) < 1e-9);
        QVERIFY(fromMesh.centreOfMass.norm() < 1e-9 * size.norm());
        QVERIFY(matrixError(fromMesh.inertia, analytic.inertia) < 1e-9);
    }

    void rotatedOffsetBoxMeshCarriesItsFrame() {
        const Vec3d size(0.2, 0.3, 0.5);
        const Quatd rotation(Eigen::AngleAxisd(0.7, Vec3d(1, 2, 3).normalized()));
        const Vec3d offset(1.5, -2.0, 0.25);
        const TriangleMesh moved = boxMesh(size).transformed(1.0, rotation, offset);
        const MassProperties fromMesh = MassProperties::ofMesh(moved, kDensity);
        const MassProperties analytic = MassProperties::ofBox(size, kDensity);
        QVERIFY((fromMesh.centreOfMass - offset).norm() < 1e-9 * offset.norm());
        // About the centre of mass, in the mesh's axes: I' = R I Rᵀ.
        const Mat3d R = rotation.toRotationMatrix();
        QVERIFY(matrixError(fromMesh.inertia, R * analytic.inertia * R.transpose()) < 1e-9);
        QVERIFY(relativeError(fromMesh.mass, analytic.mass) < 1e-9);
    }

    void sphereMeshMatchesTheSphere() {
        // An icosphere with its vertices on the sphere is inscribed, so it falls short of the
        // sphere: with 1280 faces by 0.86 % in volume and 1.43 % in moment of inertia, errors
        // that shrink 4× per level of subdivision (they go as the edge length squared). With
        // 5120 faces the shortfall is 0.22 % and 0.36 %, well within the 1 % asked here.
        const double r = 0.1;
        writeObj(folder_.filePath("sphere.obj"), icosphere(r, 4));
        const TriangleMesh mesh = MeshLoader::load(folder_.filePath("sphere.obj").toStdString());
        QCOMPARE(mesh.triangleCount(), std::size_t(5120));
        const MassProperties fromMesh = MassProperties::ofMesh(mesh, kDensity);
        const MassProperties analytic = MassProperties::ofSphere(r, kDensity);
        const double volumeError = relativeError(fromMesh.volume, analytic.volume);
        const double inertiaError = matrixError(fromMesh.inertia, analytic.inertia);
        qInfo("5120-face icosphere: volume %.3f %% short, inertia %.3f %% off", 100 * volumeError,
              100 * inertiaError);
        QVERIFY(volumeError < 0.01);
        QVERIFY(inertiaError < 0.01);
        QVERIFY(fromMesh.centreOfMass.norm() < 1e-6 * r); // symmetric, up to float positions
    }

    void offsetSphereMeshShiftsOnlyItsCentre() {
        const double r = 0.1;
        const Vec3d offset(0.3, 1.2, -0.4);
        const TriangleMesh centred = icosphere(r, 3);
        const MassProperties atOrigin = MassProperties::ofMesh(centred, kDensity);
        const MassProperties moved = MassProperties::ofMesh(
            centred.transformed(1.0, Quatd(Eigen::AngleAxisd(1.1, Vec3d::UnitZ())), offset),
            kDensity);
        QVERIFY((moved.centreOfMass - offset).norm() < 1e-9 * r);
        QVERIFY(relativeError(moved.volume, atOrigin.volume) < 1e-9);
        // The icosphere is nearly isotropic, so its inertia hardly changes when turned.
        QVERIFY(matrixError(moved.inertia, atOrigin.inertia) < 1e-3);
    }

    void bunny() {
        const TriangleMesh bunny =
            MeshLoader::load(std::string(AIRTRAP_SOURCE_DIR) + "/tests/data/bunny_lowres.obj");
        const MassProperties mass = MassProperties::ofMesh(bunny, 1000.0);
        const Aabb bounds = bunny.bounds();
        qInfo("bunny: volume %.4e m³, centre of mass (%.4f, %.4f, %.4f) m", mass.volume,
              mass.centreOfMass.x(), mass.centreOfMass.y(), mass.centreOfMass.z());
        QVERIFY(relativeError(mass.volume, 7.527e-4) < 1e-3); // bunny.SOURCE.txt
        QVERIFY(bounds.contains(mass.centreOfMass));
        // A real inertia tensor: symmetric, positive, each principal moment at most the sum of
        // the other two (triangle inequality of moments).
        QVERIFY((mass.inertia - mass.inertia.transpose()).norm() < 1e-12 * mass.inertia.norm());
        const Vec3d moments = Eigen::SelfAdjointEigenSolver<Mat3d>(mass.inertia).eigenvalues();
        QVERIFY(moments.minCoeff() > 0.0);
        QVERIFY(moments[2] <= moments[0] + moments[1]);
    }
};

AIRTRAP_TEST_APPLESS(TestMassProperties)
#include "TestMassProperties.moc"
