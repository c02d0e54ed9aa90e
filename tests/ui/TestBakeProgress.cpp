// The bake's progress in the status bar: the share of the frame range with the current frame as
// its finer part, never going back; an ETA from the time the bake ran, pauses left out; a
// visible Paused state; and Pause and Resume in the log.
#include "BakeTestScenes.h"
#include "bake/BakeProgress.h"
#include "controller/BakeProgressMeter.h"
#include "controller/SimulationController.h"
#include "scene/SceneJson.h"
#include "support/WidgetTestMain.h"
#include "window/EditorActions.h"
#include "window/LogPanel.h"
#include "window/MainWindow.h"
#include "window/StatusBarFields.h"

#include <QAction>
#include <QLabel>
#include <QProgressBar>
#include <QSignalSpy>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QTest>

namespace airtrap {

namespace {

BakeProgress report(int frame, int lastFrame, double frameFraction) {
    BakeProgress progress;
    progress.frame = frame;
    progress.lastFrame = lastFrame;
    progress.frameFraction = frameFraction;
    progress.stepsPerSecond = 50.0;
    return progress;
}

} // namespace

class TestBakeProgress : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void theShareCountsFramesDoneAndTheCurrentFrame() {
        BakeProgressMeter meter;
        meter.start(0.0);
        // Frames 2..11 are computed (frame 1 is the initial state): ten frames.
        QCOMPARE(meter.update(report(2, 11, 0.0)), 0.0);
        QCOMPARE(meter.update(report(2, 11, 0.5)), 0.05);
        QCOMPARE(meter.update(report(7, 11, 0.25)), 0.525);
        QCOMPARE(meter.update(report(11, 11, 1.0)), 1.0);
    }

    void theShareNeverGoesBack() {
        BakeProgressMeter meter;
        meter.start(0.0);
        meter.update(report(5, 11, 0.9));
        // A frame's last report and the next frame's first step: no step backwards, even when
        // a late report of the earlier frame arrives after it.
        QCOMPARE(meter.update(report(6, 11, 0.0)), 0.4);
        QCOMPARE(meter.update(report(5, 11, 0.95)), 0.4);
        QCOMPARE(meter.update(report(6, 11, 0.1)), 0.41);
    }

    void theEtaLeavesPausesOut() {
        BakeProgressMeter meter;
        meter.start(100.0);
        QCOMPARE(meter.etaSeconds(100.0), -1.0);
        meter.update(report(2, 11, 0.0));
        meter.update(report(4, 11, 0.0)); // 20 % in 10 s: 40 s to go
        QCOMPARE(meter.etaSeconds(110.0), 40.0);
        meter.pause(110.0);
        QVERIFY(meter.isPaused());
        QCOMPARE(meter.etaSeconds(500.0), 40.0); // a pause does not age the estimate
        meter.resume(600.0);
        meter.update(report(6, 11, 0.0)); // 40 % in 10 + 20 s of running: 45 s to go
        QCOMPARE(meter.etaSeconds(620.0), 45.0);
    }

    void aResumedBakeMeasuresItsRateFromWhereItBegan() {
        BakeProgressMeter meter;
        meter.start(0.0);
        meter.update(report(6, 11, 0.0)); // resumed after frame 5: 40 % before it started
        meter.update(report(8, 11, 0.0)); // 20 % more in 10 s
        QCOMPARE(meter.etaSeconds(10.0), 20.0);
    }

    void theBarShowsFrameShareAndPause() {
        QStatusBar bar;
        StatusBarFields fields(&bar);
        QVERIFY(fields.bakeProgressBar()->isHidden());
        fields.showBakeProgress(report(7, 11, 0.25), 0.525, 75.0);
        QVERIFY(!fields.bakeProgressBar()->isHidden());
        QCOMPARE(fields.bakeProgressBar()->value(), 525);
        QCOMPARE(fields.bakeProgressBar()->text(), QStringLiteral("Frame 7 of 11 · 52 %"));
        QCOMPARE(fields.etaField()->text(), QStringLiteral("ETA 1 min 15 s"));
        QCOMPARE(fields.stepField()->text(), QStringLiteral("20.0 ms/step"));
        fields.showBakePaused(7, 11, 0.525);
        QCOMPARE(fields.bakeProgressBar()->text(), QStringLiteral("Paused · frame 7 of 11 · 52 %"));
        QCOMPARE(fields.bakeProgressBar()->value(), 525);
        QCOMPARE(fields.etaField()->text(), QStringLiteral("Paused"));
        // 99.96 % is not yet done.
        fields.showBakeProgress(report(11, 11, 0.996), 0.9996, 1.0);
        QCOMPARE(fields.bakeProgressBar()->text(), QStringLiteral("Frame 11 of 11 · 99 %"));
        fields.clearBake();
        QVERIFY(fields.bakeProgressBar()->isHidden());
        QVERIFY(fields.etaField()->text().isEmpty());
    }

    //! A real bake in the editor: the bar only moves forward, Pause shows and logs, Resume logs,
    //! the bar goes when the bake ends.
    void aBakeInTheEditorFillsTheBarOnceAndLogsPauseAndResume() {
        QTemporaryDir folder;
        Scene scene = test::tinyDamBreak();
        // Enough frames that the pause falls well before the end on a fast machine.
        scene.frames.endFrame = 60;
        const QString scenePath = folder.filePath(QStringLiteral("tiny.json"));
        writeSceneFile(scene, scenePath.toStdString());
        MainWindow window;
        window.setInteractive(false);
        window.show();
        QVERIFY(window.openScene(scenePath));
        QProgressBar* bar = window.statusFields()->bakeProgressBar();
        QList<int> values;
        connect(bar, &QProgressBar::valueChanged, this, [&values](int value) { values << value; });
        QSignalSpy frames(window.controller(), &SimulationController::frameFinished);

        // Paused as soon as frame 2 lands, the way a user's click arrives between two events.
        connect(window.controller(), &SimulationController::frameFinished, &window,
                [&window](int frame) {
                    if (frame == 2)
                        window.actions().pause->trigger();
                });
        window.actions().bake->trigger();
        QTRY_VERIFY_WITH_TIMEOUT(frames.count() >= 2, 60000);
        QVERIFY(bar->isVisible());
        QVERIFY2(bar->text().startsWith(QStringLiteral("Paused · frame ")),
                 qPrintable(bar->text()));
        QCOMPARE(window.statusFields()->etaField()->text(), QStringLiteral("Paused"));
        QVERIFY(window.log()->toPlainText().contains(QStringLiteral("Bake paused at frame ")));
        QTest::qWait(300); // reports queued before the pause keep the bar paused
        QVERIFY2(bar->text().startsWith(QStringLiteral("Paused")), qPrintable(bar->text()));

        window.actions().resume->trigger();
        QVERIFY(window.log()->toPlainText().contains(QStringLiteral("Bake resumed at frame ")));
        QTRY_VERIFY_WITH_TIMEOUT(!window.controller()->isBusy(), 60000);
        QVERIFY(bar->isHidden());
        QVERIFY2(values.size() >= 59, "the bar moved fewer times than there are frames");
        for (int i = 1; i < values.size(); ++i)
            QVERIFY2(values[i] >= values[i - 1] || values[i] == -1,
                     qPrintable(QStringLiteral("the bar went back from %1 to %2")
                                    .arg(values[i - 1])
                                    .arg(values[i])));
        // The last report before the bar went is the last frame, done.
        values.removeAll(-1);
        QCOMPARE(values.last(), 1000);
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestBakeProgress)
#include "TestBakeProgress.moc"
