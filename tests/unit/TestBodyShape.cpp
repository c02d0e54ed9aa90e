// Signed distances and normals of the analytic body shapes (rigid–rigid contacts and placement
// checks rest on them): exact values at chosen points, and normals that agree with the distance's
// gradient everywhere.
#include "rigid/BodyShape.h"
#include "support/TestMain.h"

#include <QtTest>
#include <random>
#include <vector>

using namespace airtrap;

namespace {

Vec3d numericGradient(const BodyShape& shape, const Vec3d& x) {
    constexpr double h = 1e-6;
    Vec3d g;
    for (int axis = 0; axis < 3; ++axis) {
        Vec3d step = Vec3d::Zero();
        step[axis] = h;
        g[axis] = (shape.signedDistance(x + step) - shape.signedDistance(x - step)) / (2 * h);
    }
    return g;
}

//! One shape of each analytic kind, the tank a 2 m box about the origin.
std::vector<BodyShape> analyticShapes() {
    return {BodyShape::box(Vec3d(0.3, 0.5, 0.7)), BodyShape::sphere(0.4),
            BodyShape::cylinder(0.3, 0.8), BodyShape::tank({Vec3d(-1, -1, -1), Vec3d(1, 1, 1)})};
}

QString where(const BodyShape& shape, const Vec3d& x) {
    return QString("shape %1 at (%2, %3, %4)")
        .arg(int(shape.kind()))
        .arg(x.x())
        .arg(x.y())
        .arg(x.z());
}

} // namespace

class TestBodyShape : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void boxDistances() {
        const BodyShape box = BodyShape::box(Vec3d(0.2, 0.4, 0.6));
        QCOMPARE(box.signedDistance(Vec3d(0.3, 0.0, 0.0)), 0.2);
        QCOMPARE(box.signedDistance(Vec3d(0.0, 0.0, 0.0)), -0.1);
        QVERIFY(std::abs(box.signedDistance(Vec3d(0.4, 0.5, 0.0)) - std::hypot(0.3, 0.3)) < 1e-12);
        QCOMPARE(box.normal(Vec3d(0.0, -0.15, 0.0)), Vec3d(0.0, -1.0, 0.0));
    }

    void sphereAndCylinderDistances() {
        const BodyShape sphere = BodyShape::sphere(0.5);
        QCOMPARE(sphere.signedDistance(Vec3d(0.0, 2.0, 0.0)), 1.5);
        QCOMPARE(sphere.normal(Vec3d(3.0, 0.0, 0.0)), Vec3d(1.0, 0.0, 0.0));
        const BodyShape cylinder = BodyShape::cylinder(0.5, 2.0);
        QCOMPARE(cylinder.signedDistance(Vec3d(1.0, 0.0, 0.0)), 0.5);                   // beside
        QCOMPARE(cylinder.signedDistance(Vec3d(0.0, 1.5, 0.0)), 0.5);                   // above
        QCOMPARE(cylinder.signedDistance(Vec3d(0.0, 0.0, 0.0)), -0.5);                  // inside
        QVERIFY(std::abs(cylinder.signedDistance(Vec3d(0.8, 1.4, 0.0)) - 0.5) < 1e-12); // rim
    }

    void tankIsSolidOutsideItsBox() {
        const BodyShape tank = BodyShape::tank({Vec3d(-1, -1, -1), Vec3d(1, 1, 1)});
        QCOMPARE(tank.signedDistance(Vec3d(0.0, -0.8, 0.0)), 0.2);  // above the floor
        QCOMPARE(tank.signedDistance(Vec3d(0.0, -1.1, 0.0)), -0.1); // in the floor
        QCOMPARE(tank.signedDistance(Vec3d(0.95, 0.0, 0.0)), 0.05); // by the +x wall
        QCOMPARE(tank.normal(Vec3d(0.95, 0.0, 0.0)), Vec3d(-1.0, 0.0, 0.0));
        QCOMPARE(tank.normal(Vec3d(0.0, -0.9, 0.0)), Vec3d(0.0, 1.0, 0.0));
        // Above the rim the walls end: only the floor is left below.
        QCOMPARE(tank.signedDistance(Vec3d(1.5, 1.5, 0.0)), 2.5);
        QVERIFY(!std::isfinite(tank.boundingRadius()));
    }

    void normalsFollowTheDistanceGradient() {
        const std::vector<BodyShape> shapes = analyticShapes();
        std::mt19937 random(7);
        std::uniform_real_distribution<double> coordinate(-0.9, 0.9);
        for (const BodyShape& shape : shapes)
            for (int sample = 0; sample < 500; ++sample) {
                const Vec3d x(coordinate(random), coordinate(random), coordinate(random));
                const Vec3d g = numericGradient(shape, x);
                if (std::abs(g.norm() - 1.0) > 1e-3)
                    continue; // on a ridge of the distance (medial axis): no single gradient
                QVERIFY2((shape.normal(x) - g).norm() < 1e-4, qPrintable(where(shape, x)));
            }
    }

    void clearanceBoundsNeverExceedTheDistanceNorChangeFasterThanIt() {
        // A contact search skips a whole body on this bound: a point within r of x must lie at
        // least clearanceBound(x) − r from the solid. Points run over and around the tank's rim,
        // where its own distance jumps.
        const std::vector<BodyShape> shapes = analyticShapes();
        std::mt19937 random(11);
        std::uniform_real_distribution<double> coordinate(-1.6, 1.6);
        std::uniform_real_distribution<double> offset(-0.3, 0.3);
        for (const BodyShape& shape : shapes)
            for (int sample = 0; sample < 2000; ++sample) {
                const Vec3d x(coordinate(random), coordinate(random), coordinate(random));
                const Vec3d y = x + Vec3d(offset(random), offset(random), offset(random));
                const double bound = shape.clearanceBound(x);
                QVERIFY(bound <= shape.signedDistance(x) + 1e-12);
                QVERIFY2(shape.signedDistance(y) >= bound - (y - x).norm() - 1e-12,
                         qPrintable(where(shape, x)));
            }
        // Inside the tank, below the rim, the bound is the distance itself.
        const BodyShape tank = BodyShape::tank({Vec3d(-1, -1, -1), Vec3d(1, 1, 1)});
        QCOMPARE(tank.clearanceBound(Vec3d(0.95, 0.0, 0.0)), 0.05);
        QCOMPARE(tank.clearanceBound(Vec3d(0.0, -0.8, 0.0)), 0.2);
    }
};

AIRTRAP_TEST_APPLESS(TestBodyShape)
#include "TestBodyShape.moc"
