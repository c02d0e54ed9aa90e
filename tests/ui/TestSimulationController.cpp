// The editor's bake controller: bakes on its own thread and reports on the GUI thread, stops
// within a step, pauses without losing anything, and reports engine errors as failed().
#include "BakeTestScenes.h"
#include "controller/SimulationController.h"
#include "support/WidgetTestMain.h"
#include "timeline/TimelineWidget.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QThread>

namespace airtrap {

using State = SimulationController::State;

namespace {

//! What the controller reported, in the order it arrived.
struct Recording {
    QList<int> frames;
    QList<BakeProgress> progress;
    //! "p<frame>" for progress and "f<frame>" for frameFinished, to check their order.
    QStringList sequence;
    bool allOnGuiThread = true;
};

void record(SimulationController& controller, Recording& recording) {
    const auto onGuiThread = [&recording] {
        recording.allOnGuiThread &= QThread::currentThread() == qApp->thread();
    };
    QObject::connect(&controller, &SimulationController::progress, &controller,
                     [&recording, onGuiThread](const BakeProgress& progress) {
                         onGuiThread();
                         recording.progress << progress;
                         recording.sequence << QStringLiteral("p%1").arg(progress.frame);
                     });
    QObject::connect(&controller, &SimulationController::frameFinished, &controller,
                     [&recording, onGuiThread](int frame, const FrameStats&) {
                         onGuiThread();
                         recording.frames << frame;
                         recording.sequence << QStringLiteral("f%1").arg(frame);
                     });
}

//! The sample dam break with ~25 000 particles: a frame takes seconds, a step a fraction of one.
Scene heavyDamBreak() {
    Scene scene = test::sampleDamBreak();
    scene.frames.endFrame = 3;
    return scene;
}

} // namespace

class TestSimulationController : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void bakesOnWorkerAndReportsOnGuiThread() {
        QTemporaryDir dir;
        SimulationController controller;
        Recording recording;
        record(controller, recording);
        TimelineWidget timeline;
        timeline.setFrameRange(1, 4);
        connect(&controller, &SimulationController::frameFinished, &timeline,
                [&timeline](int frame) { timeline.addCachedFrame(frame); });
        QSignalSpy states(&controller, &SimulationController::stateChanged);
        QSignalSpy finished(&controller, &SimulationController::finished);

        QElapsedTimer clock;
        clock.start();
        controller.bake(test::tinyDamBreak(), dir.path(), false);
        QVERIFY2(clock.elapsed() < 200, "bake() must return at once");
        QCOMPARE(controller.state(), State::Running);
        QVERIFY(controller.isBusy());
        QCOMPARE(controller.cacheDir(), dir.path());
        QVERIFY(finished.wait(30000));
        const qint64 bakeMs = clock.elapsed();

        QCOMPARE(finished.first().at(0).toBool(), true);
        QCOMPARE(finished.first().at(1).toString(), QStringLiteral("complete"));
        QCOMPARE(controller.state(), State::Idle);
        QCOMPARE(states.count(), 2);
        QCOMPARE(states.at(1).at(0).value<State>(), State::Idle);
        QVERIFY(recording.allOnGuiThread);
        QCOMPARE(recording.frames, QList<int>({1, 2, 3, 4}));
        QCOMPARE(timeline.cachedFrames(), QList<int>({1, 2, 3, 4}));
        QCOMPARE(FrameCache::open(dir.path().toStdString()).frames(),
                 std::vector<int>({1, 2, 3, 4}));
        checkProgressThrottled(recording, bakeMs);
        QVERIFY(!QTest::currentTestFailed());
    }

    void stopEndsWithinAStep() {
        QTemporaryDir dir;
        SimulationController controller;
        Recording recording;
        record(controller, recording);
        QSignalSpy finished(&controller, &SimulationController::finished);
        controller.bake(heavyDamBreak(), dir.path(), false);

        // Let frame 2 get under way, then measure how long the stop takes.
        QTRY_VERIFY_WITH_TIMEOUT(!recording.progress.isEmpty(), 20000);
        QElapsedTimer frameClock;
        frameClock.start();
        QTest::qWait(500);
        const double fraction = recording.progress.last().frameFraction;
        QVERIFY(fraction > 0.0);
        const double projectedFrameMs = frameClock.elapsed() / fraction;

        QElapsedTimer stopClock;
        stopClock.start();
        controller.stop();
        QCOMPARE(controller.state(), State::Stopping);
        QVERIFY(controller.waitForIdle(5000));
        const qint64 stopMs = stopClock.elapsed();
        qInfo("stop took %lld ms; a frame takes about %.0f ms", stopMs, projectedFrameMs);

        QCOMPARE(controller.state(), State::Idle);
        QVERIFY2(stopMs < 2000, qPrintable(QStringLiteral("stop took %1 ms").arg(stopMs)));
        QVERIFY2(stopMs < projectedFrameMs / 2, "the stop must not wait for the frame to end");
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.first().at(0).toBool(), false);
        QCOMPARE(finished.first().at(1).toString(), QStringLiteral("stopped at frame 1"));
        const FrameCache cache = FrameCache::open(dir.path().toStdString());
        QCOMPARE(cache.frames(), std::vector<int>({1}));
        QVERIFY(cache.verify().empty());
    }

    void pauseHoldsAndResumeContinuesTheSameBake() {
        // Long enough (about a second) that an unpaused bake would report during the checks.
        Scene scene = test::tinyDamBreak();
        scene.frames.endFrame = 16;
        QTemporaryDir reference;
        test::bakeNow(scene, reference.path());

        QTemporaryDir dir;
        SimulationController controller;
        Recording recording;
        record(controller, recording);
        QSignalSpy finished(&controller, &SimulationController::finished);
        controller.bake(scene, dir.path(), false);
        QTRY_VERIFY_WITH_TIMEOUT(!recording.progress.isEmpty(), 20000);
        controller.pause();
        QCOMPARE(controller.state(), State::Paused);
        // Reports already under way when the pause arrived may still come in; then nothing.
        QTest::qWait(200);
        const qsizetype progressWhenPaused = recording.progress.size();
        const qsizetype framesWhenPaused = recording.frames.size();
        QTest::qWait(300);
        QCOMPARE(recording.progress.size(), progressWhenPaused);
        QCOMPARE(recording.frames.size(), framesWhenPaused);
        // Paused before the end: how many frames came first depends on the machine's speed.
        QVERIFY(recording.frames.size() < scene.frames.endFrame);

        controller.resume();
        QCOMPARE(controller.state(), State::Running);
        QVERIFY(finished.wait(30000));
        QCOMPARE(finished.first().at(0).toBool(), true);
        QCOMPARE(recording.frames.size(), 16);
        const FrameData paused = FrameCache::open(dir.path().toStdString()).readFrame(16);
        const FrameData uninterrupted =
            FrameCache::open(reference.path().toStdString()).readFrame(16);
        QVERIFY2(paused.state == uninterrupted.state,
                 "a paused bake must match an uninterrupted one");
    }

    void stopWakesAPausedBake() {
        QTemporaryDir dir;
        SimulationController controller;
        Recording recording;
        record(controller, recording);
        QSignalSpy finished(&controller, &SimulationController::finished);
        // Long enough that it cannot end on its own between the first progress and the pause.
        Scene scene = test::tinyDamBreak();
        scene.frames.endFrame = 200;
        controller.bake(scene, dir.path(), false);
        QTRY_VERIFY_WITH_TIMEOUT(!recording.progress.isEmpty(), 20000);
        controller.pause();
        QTest::qWait(100);
        controller.stop();
        QVERIFY(controller.waitForIdle(2000));
        QCOMPARE(finished.count(), 1);
        QCOMPARE(finished.first().at(0).toBool(), false);
        QVERIFY(FrameCache::open(dir.path().toStdString()).verify().empty());
    }

    void resumeContinuesFromTheLastGoodFrame() {
        QTemporaryDir dir;
        test::bakeNow(test::tinyDamBreak(), dir.path());
        FrameCache::open(dir.path().toStdString()).truncateAfter(2);
        SimulationController controller;
        Recording recording;
        record(controller, recording);
        QSignalSpy messages(&controller, &SimulationController::message);
        controller.bake(test::tinyDamBreak(), dir.path(), true);
        QVERIFY(controller.waitForIdle(30000));
        QCOMPARE(recording.frames, QList<int>({3, 4}));
        QVERIFY(!messages.isEmpty());
        QVERIFY(
            messages.first().at(0).toString().contains(QStringLiteral("continuing from frame 2")));
    }

    void engineErrorReportsFailedAndReturnsToIdle() {
        QTemporaryDir dir;
        const QString file = dir.filePath(QStringLiteral("plain.txt"));
        QFile(file).open(QIODevice::WriteOnly);
        const QString cacheDir = file + QStringLiteral("/cache");
        SimulationController controller;
        QSignalSpy failed(&controller, &SimulationController::failed);
        QSignalSpy finished(&controller, &SimulationController::finished);
        controller.bake(test::tinyDamBreak(), cacheDir, false);
        QVERIFY(failed.wait(10000));
        const QString message = failed.first().at(0).toString();
        QVERIFY2(message.contains(cacheDir), qPrintable(message));
        QCOMPARE(controller.state(), State::Idle);
        QCOMPARE(finished.count(), 0);
    }

    void invalidSceneReportsFailed() {
        Scene scene = test::tinyDamBreak();
        scene.fluidBlocks.at(0).max = Vec3d(5.0, 0.4, 0.2);
        QTemporaryDir dir;
        SimulationController controller;
        QSignalSpy failed(&controller, &SimulationController::failed);
        controller.bake(scene, dir.path(), false);
        QVERIFY(failed.wait(10000));
        QVERIFY2(failed.first().at(0).toString().contains(QStringLiteral("fluid_blocks")),
                 qPrintable(failed.first().at(0).toString()));
        QCOMPARE(controller.state(), State::Idle);
        QVERIFY(!FrameCache::isCache(dir.path().toStdString()));
    }

    void discardsFramesOnlyWhenIdle() {
        QTemporaryDir dir;
        test::bakeNow(test::tinyDamBreak(), dir.path());
        SimulationController controller;
        QSignalSpy failed(&controller, &SimulationController::failed);
        controller.discardFramesAfter(dir.path(), 2);
        QCOMPARE(failed.count(), 0);
        QCOMPARE(FrameCache::open(dir.path().toStdString()).frames(), std::vector<int>({1, 2}));

        QTemporaryDir notACache;
        controller.discardFramesAfter(notACache.path(), 1);
        QCOMPARE(failed.count(), 1);
        QVERIFY(failed.first().at(0).toString().contains(notACache.path()));

        QTemporaryDir other;
        controller.bake(test::tinyDamBreak(), other.path(), false);
        controller.discardFramesAfter(dir.path(), 1);
        QCOMPARE(failed.count(), 2);
        QCOMPARE(FrameCache::open(dir.path().toStdString()).frames(), std::vector<int>({1, 2}));
        QVERIFY(controller.waitForIdle(30000));
    }

    void destructorStopsARunningBake() {
        QTemporaryDir dir;
        QElapsedTimer clock;
        {
            SimulationController controller;
            Recording recording;
            record(controller, recording);
            controller.bake(heavyDamBreak(), dir.path(), false);
            QTRY_VERIFY_WITH_TIMEOUT(!recording.progress.isEmpty(), 20000);
            clock.start();
        }
        QVERIFY2(clock.elapsed() < 2000, "destroying the controller must not finish the frame");
        QVERIFY(FrameCache::open(dir.path().toStdString()).verify().empty());
    }

private:
    //! At most one report per 50 ms plus the last one of each frame, which always comes.
    static void checkProgressThrottled(const Recording& recording, qint64 bakeMs) {
        const qsizetype bound = bakeMs / 50 + 2 * recording.frames.size() + 2;
        QVERIFY2(
            recording.progress.size() <= bound,
            qPrintable(
                QStringLiteral("%1 reports in %2 ms").arg(recording.progress.size()).arg(bakeMs)));
        for (qsizetype i = 1; i < recording.sequence.size(); ++i) {
            const QString& entry = recording.sequence.at(i);
            if (!entry.startsWith('f') || entry == QStringLiteral("f1"))
                continue;
            QCOMPARE(recording.sequence.at(i - 1), QStringLiteral("p") + entry.mid(1));
        }
        for (const BakeProgress& progress : recording.progress)
            QCOMPARE(progress.lastFrame, 4);
        QCOMPARE(recording.progress.last().frameFraction, 1.0);
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestSimulationController)
#include "TestSimulationController.moc"
