// A kinematic body follows its keyframes exactly — at every cached frame its pose is the path's
// pose at that frame's time, bit for bit — and pushes the water without being pushed back.
#include "rigid/EulerRotation.h"
#include "rigid/KeyframedPath.h"
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/SolverMethods.h"
#include "support/TestMain.h"

#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

class TestKinematicBody : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void paddleFollowsItsKeyframes_data() { test::addSolverMethodRows(); }
    void paddleFollowsItsKeyframes() {
        QFETCH(QString, method);
        RigidBodySettings paddle;
        paddle.name = "Paddle";
        paddle.motion = "kinematic";
        paddle.size = Vec3d(0.04, 0.3, 0.2);
        paddle.position = Vec3d(0.2, 0.2, 0.15);
        Scene scene = SceneBuilder()
                          .spacing(0.02)
                          .maxSpeed(3.0)
                          .frames(25.0, 1 + 15) // 0.6 s
                          .tank({0.8, 0.4, 0.3})
                          .water({0.0, 0.0, 0.0}, {0.8, 0.2, 0.3})
                          .body(paddle)
                          .build();
        scene.solver.method = method.toStdString();
        // Sweeps right, turning 20° about z, then holds; the middle key falls between frames.
        scene.keyframes = {{"Paddle", 0.0, Vec3d(0.2, 0.2, 0.15), Vec3d::Zero()},
                           {"Paddle", 0.33, Vec3d(0.4, 0.2, 0.15), Vec3d(0.0, 0.0, -20.0)},
                           {"Paddle", 0.5, Vec3d(0.45, 0.22, 0.15), Vec3d(0.0, 0.0, -20.0)}};
        std::vector<KeyframedPath::Keyframe> keys;
        for (const BodyKeyframe& key : scene.keyframes)
            keys.push_back({key.time, key.position, EulerRotation::fromDegrees(key.rotation)});
        const KeyframedPath path(keys);

        Simulation simulation(scene);
        Interrupter interrupter;
        double fastestWater = 0.0;
        while (simulation.frame() < scene.frames.endFrame) {
            simulation.advanceFrame(interrupter);
            const RigidBodyState& body = simulation.state().bodies[0];
            const RigidPose expected = path.poseAt(simulation.state().time);
            QVERIFY2(body.position == expected.position,
                     qPrintable(QString("frame %1: position off by %2 m")
                                    .arg(simulation.frame())
                                    .arg((body.position - expected.position).norm())));
            QVERIFY(body.orientation.coeffs() == expected.orientation.coeffs());
            QVERIFY(body.linearVelocity == path.velocityAt(simulation.state().time).linear);
            for (const Vec3f& v : simulation.state().fluid.velocities)
                fastestWater = std::max(fastestWater, double(v.norm()));
        }
        // The paddle moved at 0.6 m/s: the water it pushed must have moved comparably.
        QVERIFY2(fastestWater > 0.3, qPrintable(QString("water at most %1 m/s").arg(fastestWater)));
        const RigidPose last = path.poseAt(10.0);
        QCOMPARE(simulation.state().bodies[0].position, last.position);
    }
};

AIRTRAP_TEST_APPLESS(TestKinematicBody)
#include "TestKinematicBody.moc"
