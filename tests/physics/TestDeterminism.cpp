// A bake is a pure function of the scene: the same bits on 1 or 2 threads, and a bake resumed
// from a cached frame continues bit-for-bit like one that never stopped.
#include "BubbleTestSupport.h"
#include "cache/FrameCache.h"
#include "core/ThreadLimit.h"
#include "scene/SceneJson.h"
#include "sim/Simulation.h"
#include "support/SceneBuilder.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

//! A small splash: a block of water thrown against a wall and a floating ball, past a paddle
//! moving at constant velocity, so every term of the step is active — the bodies' coupling and
//! contacts included.
Scene splash(const std::string& method = "wcsph") {
    SceneBuilder builder;
    builder.scene().solver.method = method;
    builder.spacing(0.025).maxSpeed(4.0).frames(60.0, 7).tank({0.5, 0.4, 0.3});
    builder.water({0.0, 0.0, 0.0}, {0.2, 0.25, 0.3}, {1.5, 0.0, 0.0});
    builder.scene().solver.shepardInterval = 7; // several re-initialisations within the run
    RigidBodySettings ball;
    ball.name = "Ball";
    ball.shape = "sphere";
    ball.radius = 0.05;
    ball.position = Vec3d(0.28, 0.05, 0.15); // on the floor, in the splash's way
    builder.body(ball);
    RigidBodySettings paddle;
    paddle.name = "Paddle";
    paddle.motion = "kinematic";
    paddle.size = Vec3d(0.05, 0.1, 0.1);
    paddle.position = Vec3d(0.42, 0.3, 0.15);
    paddle.linearVelocity = Vec3d(0.0, -0.5, 0.0);
    paddle.angularVelocity = Vec3d(0.0, 0.0, 2.0);
    return builder.body(paddle).build();
}

//! The splash with bubbles: two placed in the water at t = 0, and pockets searched every 0.5 ms.
Scene splashWithBubbles(const std::string& method) {
    Scene scene = splash(method);
    scene.bubbles.enabled = true;
    scene.bubbles.pocketInterval = 0.0005;
    scene.bubbles.maxFloatingTime = 0.02;
    scene.bubbles.maxAge = 0.05; // so that deletions happen within the run
    return scene;
}

std::vector<BubbleState> twoBubbles() {
    return {test::bubbleAt(0, Vec3d(0.1, 0.1, 0.1), 0.04),
            test::bubbleAt(1, Vec3d(0.1, 0.15, 0.2), 0.035)};
}

SimulationState bakeFrom(Simulation& simulation, int lastFrame) {
    Interrupter interrupter;
    while (simulation.frame() < lastFrame)
        simulation.advanceFrame(interrupter);
    return simulation.state();
}

//! Rows for each pressure solver: the method and the fewest steps the splash must take (DFSPH's
//! step is limited by the flow alone, so it takes far fewer).
void methodRows() {
    QTest::addColumn<QString>("method");
    QTest::addColumn<int>("minimumSteps");
    QTest::newRow("wcsph") << "wcsph" << 50;
    QTest::newRow("dfsph") << "dfsph" << 12;
}

std::string methodOfRow() {
    QFETCH(QString, method);
    return method.toStdString();
}

} // namespace

class TestDeterminism : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void sameBitsOnOneAndTwoThreads_data() { methodRows(); }
    void sameBitsOnOneAndTwoThreads() {
        QFETCH(int, minimumSteps);
        const Scene scene = splash(methodOfRow());
        SimulationState one, two;
        {
            ThreadLimit limit(1);
            Simulation simulation(scene);
            one = bakeFrom(simulation, 5);
        }
        {
            ThreadLimit limit(2);
            Simulation simulation(scene);
            two = bakeFrom(simulation, 5);
        }
        QVERIFY2(one.steps > std::uint64_t(minimumSteps), qPrintable(QString::number(one.steps)));
        QVERIFY2((one.bodies[0].position - Vec3d(0.28, 0.05, 0.15)).norm() > 0.005,
                 "the splash did not move the ball; the bodies' terms went untested");
        QVERIFY(one == two);
    }

    void resumeFromTheCacheIsBitIdentical_data() { methodRows(); }
    void resumeFromTheCacheIsBitIdentical() {
        const Scene scene = splash(methodOfRow());
        Simulation straight(scene);
        const SimulationState uninterrupted = bakeFrom(straight, scene.frames.endFrame);

        QTemporaryDir dir;
        const std::string path = dir.filePath("cache").toStdString();
        {
            FrameCache cache =
                FrameCache::create(path, sceneToJson(scene), parameterHash(scene), 60.0);
            Simulation first(scene);
            bakeFrom(first, 3);
            cache.writeFrame(first.state(), first.lastFrameStats());
        }
        const FrameCache reopened = FrameCache::open(path);
        Simulation resumed(scene, reopened.readFrame(3).state);
        const SimulationState continued = bakeFrom(resumed, scene.frames.endFrame);

        QCOMPARE(continued.frame, uninterrupted.frame);
        QCOMPARE(continued.steps, uninterrupted.steps);
        QVERIFY(continued.fluid.positions == uninterrupted.fluid.positions);
        // DFSPH's solves start from the cached warm start; without it they would differ.
        QCOMPARE(continued.warmStart.empty(), scene.solver.method == "wcsph");
        QVERIFY(continued == uninterrupted);
    }

    void bubblesAreDeterministicAndResumeBitIdentical_data() { methodRows(); }
    void bubblesAreDeterministicAndResumeBitIdentical() {
        const Scene scene = splashWithBubbles(methodOfRow());
        SimulationState one;
        {
            ThreadLimit limit(1);
            auto simulation = test::simulationWithBubbles(scene, twoBubbles());
            one = bakeFrom(*simulation, scene.frames.endFrame);
        }
        ThreadLimit limit(2);
        auto straight = test::simulationWithBubbles(scene, twoBubbles());
        const SimulationState uninterrupted = bakeFrom(*straight, scene.frames.endFrame);
        QVERIFY(one == uninterrupted);
        QVERIFY2(uninterrupted.bubblesDeleted.deletedTotal() > 0 || uninterrupted.nextBubbleId > 2,
                 "no bubble came or went: the bubbles' bookkeeping went untested");

        QTemporaryDir dir;
        const std::string path = dir.filePath("cache").toStdString();
        {
            FrameCache cache =
                FrameCache::create(path, sceneToJson(scene), parameterHash(scene), 60.0);
            auto first = test::simulationWithBubbles(scene, twoBubbles());
            bakeFrom(*first, 3);
            QVERIFY(!first->state().bubbles.empty());
            cache.writeFrame(first->state(), first->lastFrameStats());
        }
        Simulation resumed(scene, FrameCache::open(path).readFrame(3).state);
        QVERIFY(bakeFrom(resumed, scene.frames.endFrame) == uninterrupted);
    }
};

AIRTRAP_TEST_APPLESS(TestDeterminism)
#include "TestDeterminism.moc"
