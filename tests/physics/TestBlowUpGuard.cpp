// The blow-up guard stops a bake with a message naming the frame and the likely cause (density
// error, water leaving the domain), and the Baker keeps every frame finished before it,
// recording the failure in the manifest. The density guard is driven by a bound far tighter than
// the flow can meet, which is exactly the condition it watches for.
#include "bake/Baker.h"
#include "cache/FrameCache.h"
#include "core/Error.h"
#include "support/SceneBuilder.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <QtTest>

using namespace airtrap;
using airtrap::test::SceneBuilder;

namespace {

Scene collapsingColumn() {
    return SceneBuilder()
        .spacing(0.025)
        .maxSpeed(3.0)
        .frames(30.0, 20)
        .tank({0.6, 0.4, 0.2})
        .water({0.0, 0.0, 0.0}, {0.15, 0.3, 0.2})
        .build();
}

//! What a bake that stops on the blow-up guard left: the guard's message, the frames written,
//! the notices it logged and its cache folder.
struct FailedBake {
    QString message;
    std::vector<int> written;
    std::vector<std::string> notices;
    std::string cacheDir;
};

//! Bakes `scene` into `dir` until the guard stops it (message empty if it never does).
FailedBake bakeUntilStopped(const Scene& scene, const QTemporaryDir& dir) {
    FailedBake result;
    BakeOptions options;
    options.cacheDir = result.cacheDir = dir.filePath("cache").toStdString();
    Baker baker(scene, options);
    baker.onFrame([&](int frame, const FrameStats&) { result.written.push_back(frame); });
    baker.onMessage([&](const std::string& notice) { result.notices.push_back(notice); });
    Interrupter interrupter;
    try {
        baker.run(interrupter);
    } catch (const Error& error) {
        if (error.kind() == ErrorKind::SimulationBlowUp)
            result.message = QString::fromStdString(error.what());
        else
            throw;
    }
    return result;
}

} // namespace

class TestBlowUpGuard : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void frameTimesAreMetExactly() {
        Simulation simulation(collapsingColumn());
        Interrupter interrupter;
        for (int frame = 2; frame <= 4; ++frame) {
            simulation.advanceFrame(interrupter);
            QCOMPARE(simulation.frame(), frame);
            QCOMPARE(simulation.state().time, simulation.scene().frameTime(frame));
        }
    }

    void densityErrorStopsTheBakeAndKeepsGoodFrames() {
        Scene scene = collapsingColumn();
        // The column's impact on the far wall compresses it by well over 0.6 % (at rest it is 0.33
        // % at the bottom).
        scene.solver.maxDensityError = 0.006;
        QTemporaryDir dir;
        const auto [message, written, notices, cacheDir] = bakeUntilStopped(scene, dir);
        QVERIFY2(!message.isEmpty(), "the bake finished although the bound was exceeded");
        const int failedFrame = written.back() + 1;
        QVERIFY2(message.startsWith(QString("frame %1 ").arg(failedFrame)), qPrintable(message));
        QVERIFY2(message.contains("solver.max_density_error"), qPrintable(message));
        QVERIFY2(message.contains("Likely cause"), qPrintable(message));
        QVERIFY(written.size() >= 2); // frame 1 and at least one simulated frame

        const FrameCache cache = FrameCache::open(cacheDir);
        QVERIFY(cache.manifest().status.rfind("failed: frame", 0) == 0);
        QCOMPARE(cache.frames(), written);
        for (int frame : written)
            QCOMPARE(cache.readFrame(frame).state.frame, frame);
    }

    void unconvergedDensitySolveStopsTheBakeAndKeepsGoodFrames() {
        Scene scene = collapsingColumn();
        scene.solver.method = "dfsph";
        // One iteration cannot reach an average density error of 0.0001 %: every step of the
        // falling column stops at the maximum.
        scene.solver.minIterations = 0;
        scene.solver.maxIterations = 1;
        scene.solver.densityErrorTarget = 1e-6;
        QTemporaryDir dir;
        const auto [message, written, notices, cacheDir] = bakeUntilStopped(scene, dir);
        QVERIFY2(!message.isEmpty(), "the bake finished although no solve converged");
        QVERIFY(written.size() >= 2);
        QVERIFY2(message.startsWith(QString("frame %1 ").arg(written.back() + 1)),
                 qPrintable(message));
        QVERIFY2(message.contains("solver.max_iterations = 1 for 50 steps in a row") &&
                     message.contains("solver.density_error"),
                 qPrintable(message));
        // Each finished frame gave its solves' figures and how many of them stopped short.
        QVERIFY(notices.size() >= 2);
        QVERIFY2(QString::fromStdString(notices[0]).contains("and 1 (density)"),
                 notices[0].c_str());
        QVERIFY2(QString::fromStdString(notices[1]).contains("the density solve stopped at"),
                 notices[1].c_str());
        QCOMPARE(FrameCache::open(cacheDir).frames(), written);
    }

    void waterLeavingTheDomainStopsTheBake() {
        Scene scene = collapsingColumn();
        scene.container.headroom = 0.05;
        scene.fluidBlocks[0].initialVelocity = Vec3d(0.0, 4.0, 0.0); // thrown 0.8 m up
        scene.solver.maxSpeed = 5.0;
        Simulation simulation(scene);
        Interrupter interrupter;
        QString message;
        try {
            while (simulation.frame() < scene.frames.endFrame)
                simulation.advanceFrame(interrupter);
        } catch (const Error& error) {
            QCOMPARE(error.kind(), ErrorKind::SimulationBlowUp);
            message = QString::fromStdString(error.what());
        }
        QVERIFY2(message.contains("particles left the domain in one frame"), qPrintable(message));
        QVERIFY2(message.contains("headroom"), qPrintable(message));
    }
};

AIRTRAP_TEST_APPLESS(TestBlowUpGuard)
#include "TestBlowUpGuard.moc"
