// The viewport's turntable camera: fitting, picking rays and navigation, without any window.
#include "support/TestMain.h"
#include "viewport/OrbitCamera.h"

#include <QTest>
#include <cmath>

namespace airtrap {

namespace {

const QSize kViewport(640, 480);

float aspect() {
    return float(kViewport.width()) / float(kViewport.height());
}

//! The eight corners of `box`.
std::vector<QVector3D> cornersOf(const Aabb& box) {
    std::vector<QVector3D> corners;
    for (int i = 0; i < 8; ++i) {
        corners.emplace_back(float(i & 1 ? box.max.x() : box.min.x()),
                             float(i & 2 ? box.max.y() : box.min.y()),
                             float(i & 4 ? box.max.z() : box.min.z()));
    }
    return corners;
}

//! Distance from `point` to the line of `ray`.
float distanceToRay(const Ray& ray, const QVector3D& point) {
    return point.distanceToLine(ray.origin, ray.direction);
}

bool near(const QVector3D& a, const QVector3D& b, float tolerance = 1e-4f) {
    return (a - b).length() <= tolerance;
}

} // namespace

class TestOrbitCamera : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void fitPutsEveryCornerInsideTheFrustum_data() {
        QTest::addColumn<float>("yaw");
        QTest::addColumn<float>("pitch");
        QTest::newRow("default") << 25.0f << 20.0f;
        QTest::newRow("front") << 0.0f << 0.0f;
        QTest::newRow("from above") << 200.0f << 85.0f;
        QTest::newRow("from below") << 300.0f << -60.0f;
    }

    void fitPutsEveryCornerInsideTheFrustum() {
        QFETCH(float, yaw);
        QFETCH(float, pitch);
        // The dam-break domain: a long, flat tank plus headroom, not centred on the origin.
        const Aabb box{Vec3d(0.0, 0.0, 0.0), Vec3d(2.5, 2.5, 0.4)};
        OrbitCamera camera;
        camera.setAngles(yaw, pitch);
        camera.fit(box, aspect());
        QVERIFY(near(camera.target(), QVector3D(1.25f, 1.25f, 0.2f)));

        const QMatrix4x4 clip = camera.projectionMatrix(aspect()) * camera.viewMatrix();
        float largest = 0.0f;
        for (const QVector3D& corner : cornersOf(box)) {
            const QVector4D p = clip * QVector4D(corner, 1.0f);
            QVERIFY2(p.w() > 0.0f, "corner behind the eye");
            const QVector3D ndc = p.toVector3DAffine();
            for (int axis = 0; axis < 3; ++axis) {
                QVERIFY2(std::abs(ndc[axis]) <= 1.0f,
                         qPrintable(QStringLiteral("axis %1 at %2").arg(axis).arg(ndc[axis])));
                largest = std::max(largest, std::abs(ndc[axis]));
            }
        }
        // And it is a fit, not a view from far away: the box fills a good part of the view.
        QVERIFY2(largest > 0.4f, qPrintable(QString::number(largest)));
    }

    void fitOfATallViewportBacksOffFurther() {
        const Aabb box{Vec3d(-1.0, -1.0, -1.0), Vec3d(1.0, 1.0, 1.0)};
        OrbitCamera wide;
        wide.fit(box, 2.0f);
        OrbitCamera tall;
        tall.fit(box, 0.5f);
        QVERIFY(tall.distance() > wide.distance() * 1.5f);
    }

    void rayThroughTheCentrePassesThroughTheTarget() {
        OrbitCamera camera;
        camera.setTarget(QVector3D(1.0f, 2.0f, -3.0f));
        camera.setDistance(7.0f);
        camera.setAngles(130.0f, 35.0f);
        const Ray ray = camera.ray(QPointF(320.0, 240.0), kViewport);
        QVERIFY(near(ray.origin, camera.eye()));
        QCOMPARE_LT(distanceToRay(ray, camera.target()), 1e-4f);
        QVERIFY(near(ray.at(camera.distance()), camera.target(), 1e-3f));
    }

    void rayAndProjectionAgree() {
        OrbitCamera camera;
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(2, 1, 1)}, aspect());
        const QPointF pixel(100.0, 400.0);
        const Ray ray = camera.ray(pixel, kViewport);
        const QPointF back = camera.project(ray.at(3.0f), kViewport);
        QCOMPARE_LT(QLineF(pixel, back).length(), 1e-2);
    }

    void projectionPutsRightAndUpOnScreen() {
        OrbitCamera camera;
        camera.setAngles(0.0f, 0.0f); // looking along −z: x right, y up
        const QPointF centre = camera.project(camera.target(), kViewport);
        QCOMPARE_LT(QLineF(centre, QPointF(320.0, 240.0)).length(), 1e-3);
        QVERIFY(camera.project(camera.target() + QVector3D(1, 0, 0), kViewport).x() > 330.0);
        QVERIFY(camera.project(camera.target() + QVector3D(0, 1, 0), kViewport).y() < 230.0);
    }

    void orbitKeepsTargetAndDistance() {
        OrbitCamera camera;
        camera.setTarget(QVector3D(0.5f, 0.2f, 0.1f));
        camera.setDistance(4.0f);
        const QVector3D eyeBefore = camera.eye();
        camera.orbit(40.0f, -15.0f);
        QVERIFY(near(camera.target(), QVector3D(0.5f, 0.2f, 0.1f)));
        QCOMPARE_LT(std::abs((camera.eye() - camera.target()).length() - 4.0f), 1e-4f);
        QVERIFY(!near(camera.eye(), eyeBefore, 0.1f));
    }

    void pitchStopsShortOfThePoles() {
        OrbitCamera camera;
        camera.orbit(0.0f, 500.0f);
        QCOMPARE_LT(camera.pitch(), 90.0f);
        QVERIFY(std::isfinite(camera.right().length()));
        QCOMPARE_LT(std::abs(camera.right().length() - 1.0f), 1e-4f);
    }

    void zoomKeepsTargetAndScalesDistance() {
        OrbitCamera camera;
        camera.setTarget(QVector3D(1.0f, 1.0f, 1.0f));
        camera.setDistance(5.0f);
        camera.zoom(0.5f);
        QVERIFY(near(camera.target(), QVector3D(1.0f, 1.0f, 1.0f)));
        QCOMPARE(camera.distance(), 2.5f);
    }

    void zoomTowardTheCentreKeepsTarget() {
        OrbitCamera camera;
        camera.setTarget(QVector3D(1.0f, 1.0f, 1.0f));
        camera.zoomToward(QPointF(320.0, 240.0), kViewport, 0.5f);
        QVERIFY(near(camera.target(), QVector3D(1.0f, 1.0f, 1.0f), 1e-4f));
    }

    void zoomTowardTheCursorKeepsThePointUnderIt() {
        OrbitCamera camera;
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(2, 2, 2)}, aspect());
        const QPointF cursor(500.0, 120.0);
        const Ray before = camera.ray(cursor, kViewport);
        const QVector3D anchor = before.at(
            camera.distance() / QVector3D::dotProduct(before.direction, camera.forward()));
        camera.zoomToward(cursor, kViewport, 0.6f);
        QCOMPARE_LT(QLineF(camera.project(anchor, kViewport), cursor).length(), 1e-2);
    }

    void panMovesTheSceneWithTheCursor() {
        OrbitCamera camera;
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(1, 1, 1)}, aspect());
        const QVector3D target = camera.target();
        const QPointF before = camera.project(target, kViewport);
        camera.pan(QPointF(40.0, -25.0), kViewport);
        const QPointF after = camera.project(target, kViewport);
        QCOMPARE_LT(QLineF(after - before, QPointF(40.0, -25.0)).length(), 0.5);
    }

    // --- Orthographic --------------------------------------------------------------------------

    void orthographicKeepsTheScaleAtTheTarget() {
        OrbitCamera camera;
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(2, 1, 1)}, aspect());
        const QVector3D aside = camera.target() + camera.right() * 0.3f + camera.up() * 0.2f;
        const QPointF inPerspective = camera.project(aside, kViewport);
        camera.setOrthographic(true);
        QVERIFY(camera.isOrthographic());
        QCOMPARE_LT(QLineF(camera.project(aside, kViewport), inPerspective).length(), 1e-2);
        // Parallel: a point further away along the view lands on the same pixel.
        const QPointF deeper = camera.project(aside + camera.forward() * 0.8f, kViewport);
        QCOMPARE_LT(QLineF(deeper, inPerspective).length(), 1e-2);
        QCOMPARE(camera.metresPerPixel(0.1f, kViewport), camera.metresPerPixel(9.0f, kViewport));
    }

    void orthographicRaysAreParallelAndAgreeWithProjection() {
        OrbitCamera camera;
        camera.setOrthographic(true);
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(2, 1, 1)}, aspect());
        const Ray a = camera.ray(QPointF(100.0, 400.0), kViewport);
        const Ray b = camera.ray(QPointF(600.0, 20.0), kViewport);
        QVERIFY(near(a.direction, camera.forward()) && near(b.direction, camera.forward()));
        // The ray starts behind the eye: whatever the view draws, it can pick.
        QVERIFY(QVector3D::dotProduct(a.origin - camera.eye(), camera.forward()) < 0.0f);
        const QPointF back = camera.project(a.at(camera.distance() * 3.0f), kViewport);
        QCOMPARE_LT(QLineF(QPointF(100.0, 400.0), back).length(), 1e-2);
    }

    void orthographicFitShowsTheWholeBox() {
        const Aabb box{Vec3d(0.0, 0.0, 0.0), Vec3d(2.5, 2.5, 0.4)};
        OrbitCamera camera;
        camera.setOrthographic(true);
        camera.setAngles(0.0f, 0.0f);
        camera.fit(box, aspect());
        const QMatrix4x4 clip = camera.projectionMatrix(aspect()) * camera.viewMatrix();
        float largest = 0.0f;
        for (const QVector3D& corner : cornersOf(box)) {
            const QVector3D ndc = (clip * QVector4D(corner, 1.0f)).toVector3DAffine();
            QVERIFY(std::abs(ndc.x()) <= 1.0f && std::abs(ndc.y()) <= 1.0f);
            QVERIFY(std::abs(ndc.z()) <= 1.0f);
            largest = std::max({largest, std::abs(ndc.x()), std::abs(ndc.y())});
        }
        QVERIFY2(largest > 0.8f, qPrintable(QString::number(largest)));
    }

    void orthographicZoomTowardTheCursorKeepsThePointUnderIt() {
        OrbitCamera camera;
        camera.setOrthographic(true);
        camera.fit(Aabb{Vec3d(0, 0, 0), Vec3d(2, 2, 2)}, aspect());
        const QPointF cursor(500.0, 120.0);
        const QVector3D anchor = camera.ray(cursor, kViewport).at(camera.distance() * 2.0f);
        camera.zoomToward(cursor, kViewport, 0.6f);
        QCOMPARE_LT(QLineF(camera.project(anchor, kViewport), cursor).length(), 1e-2);
    }

    void rayHitsBoxesItPointsAt() {
        const Ray ray{QVector3D(0, 0, 5), QVector3D(0, 0, -1)};
        const std::optional<float> hit = ray.hitBox(QVector3D(-1, -1, -1), QVector3D(1, 1, 1));
        QVERIFY(hit);
        QCOMPARE(*hit, 4.0f);
        QVERIFY(!ray.hitBox(QVector3D(2, 2, -1), QVector3D(3, 3, 1)));
        QVERIFY(!ray.hitBox(QVector3D(-1, -1, 6), QVector3D(1, 1, 7))); // behind
    }
};

} // namespace airtrap

AIRTRAP_TEST_GUILESS(airtrap::TestOrbitCamera)
#include "TestOrbitCamera.moc"
