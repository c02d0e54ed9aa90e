// The timeline: range and clamping, stepping, the buttons, spin box and ruler, and playback at
// the scene's rate over cached frames only.
#include "support/WidgetTestMain.h"
#include "timeline/FrameRuler.h"
#include "timeline/TimelineWidget.h"

#include <QComboBox>
#include <QElapsedTimer>
#include <QLabel>
#include <QSignalSpy>
#include <QSpinBox>
#include <QTest>
#include <QToolButton>

namespace airtrap {

namespace {

//! The frames the timeline moved to, in order.
QList<int> framesVisited(const QSignalSpy& spy) {
    QList<int> frames;
    for (const QList<QVariant>& arguments : spy)
        frames << arguments.at(0).toInt();
    return frames;
}

} // namespace

class TestTimeline : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void rangeClampsTheCurrentFrame() {
        TimelineWidget timeline;
        QSignalSpy changes(&timeline, &TimelineWidget::currentFrameChanged);
        timeline.setFrameRange(1, 10);
        QCOMPARE(timeline.currentFrame(), 1);
        QCOMPARE(changes.count(), 0);
        timeline.setCurrentFrame(20);
        QCOMPARE(timeline.currentFrame(), 10);
        timeline.setCurrentFrame(-5);
        QCOMPARE(timeline.currentFrame(), 1);
        timeline.setCurrentFrame(8);
        timeline.setFrameRange(1, 5);
        QCOMPARE(timeline.currentFrame(), 5);
        QCOMPARE(framesVisited(changes), QList<int>({10, 1, 8, 5}));
        timeline.setFrameRange(7, 3);
        QCOMPARE(timeline.firstFrame(), 7);
        QCOMPARE(timeline.lastFrame(), 7);
        QCOMPARE(timeline.currentFrame(), 7);
    }

    void stepsAndJumps() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 10);
        timeline.stepForward();
        timeline.stepForward();
        QCOMPARE(timeline.currentFrame(), 3);
        timeline.stepBackward();
        QCOMPARE(timeline.currentFrame(), 2);
        timeline.goToFirst();
        timeline.stepBackward();
        QCOMPARE(timeline.currentFrame(), 1);
        timeline.goToLast();
        QCOMPARE(timeline.currentFrame(), 10); // nothing cached: the range's end
        timeline.setCachedFrames({1, 2, 3, 4});
        timeline.goToFirst();
        timeline.goToLast();
        QCOMPARE(timeline.currentFrame(), 4); // the newest cached frame
        timeline.stepForward();
        QCOMPARE(timeline.currentFrame(), 5); // stepping is not limited to cached frames
    }

    void cachedFramesAreKeptSorted() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 10);
        timeline.addCachedFrame(3);
        timeline.addCachedFrame(1);
        timeline.addCachedFrame(3);
        QCOMPARE(timeline.cachedFrames(), QList<int>({1, 3}));
        timeline.setCachedFrames({5, 2});
        QCOMPARE(timeline.cachedFrames(), QList<int>({2, 5}));
    }

    void controlsDriveTheCurrentFrame() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 50);
        timeline.resize(800, 40);
        timeline.show();
        QVERIFY(QTest::qWaitForWindowExposed(&timeline));
        const auto button = [&timeline](const char* name) {
            return timeline.findChild<QToolButton*>(QString::fromLatin1(name));
        };
        for (const char* name : {"firstButton", "stepBackButton", "playButton", "stepForwardButton",
                                 "lastButton", "loopButton"})
            QVERIFY2(button(name), name);
        button("stepForwardButton")->click();
        QCOMPARE(timeline.currentFrame(), 2);
        button("lastButton")->click();
        QCOMPARE(timeline.currentFrame(), 50);
        button("stepBackButton")->click();
        QCOMPARE(timeline.currentFrame(), 49);
        button("firstButton")->click();
        QCOMPARE(timeline.currentFrame(), 1);
        button("loopButton")->click();
        QVERIFY(timeline.loops());

        auto* spinBox = timeline.findChild<QSpinBox*>(QStringLiteral("frameSpinBox"));
        QVERIFY(spinBox);
        spinBox->setValue(17);
        QCOMPARE(timeline.currentFrame(), 17);
        timeline.setCurrentFrame(23);
        QCOMPARE(spinBox->value(), 23);
        QCOMPARE(spinBox->maximum(), 50);

        auto* ruler = timeline.findChild<FrameRuler*>(QStringLiteral("frameRuler"));
        QVERIFY(ruler);
        QTest::mouseClick(ruler, Qt::LeftButton, {}, QPoint(int(ruler->xOf(40)), 10));
        QCOMPARE(timeline.currentFrame(), 40);
        QTest::mousePress(ruler, Qt::LeftButton, {}, QPoint(int(ruler->xOf(10)), 10));
        QMouseEvent drag(QEvent::MouseMove, QPointF(ruler->xOf(30), 10),
                         ruler->mapToGlobal(QPointF(ruler->xOf(30), 10)), Qt::NoButton,
                         Qt::LeftButton, Qt::NoModifier);
        QApplication::sendEvent(ruler, &drag);
        QTest::mouseRelease(ruler, Qt::LeftButton, {}, QPoint(int(ruler->xOf(30)), 10));
        QCOMPARE(timeline.currentFrame(), 30);
        QCOMPARE(ruler->frameAt(-100), 1);
        QCOMPARE(ruler->frameAt(10000), 50);
    }

    void playAdvancesAtFpsOverCachedFramesOnly() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 8);
        timeline.setCachedFrames({1, 2, 3, 5});
        timeline.setFps(20.0);
        QSignalSpy changes(&timeline, &TimelineWidget::currentFrameChanged);
        QElapsedTimer clock;
        clock.start();
        timeline.play();
        QVERIFY(timeline.isPlaying());
        QTRY_VERIFY_WITH_TIMEOUT(!timeline.isPlaying(), 3000);
        QCOMPARE(framesVisited(changes), QList<int>({2, 3, 5}));
        // Three frames at 20 fps, then one more tick to find the end: 4 × 50 ms.
        QVERIFY2(clock.elapsed() >= 180, qPrintable(QString::number(clock.elapsed())));
    }

    void playAtTheEndStartsOver() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 8);
        timeline.setCachedFrames({1, 2, 3});
        timeline.setFps(100.0);
        timeline.setCurrentFrame(3);
        QSignalSpy changes(&timeline, &TimelineWidget::currentFrameChanged);
        timeline.play();
        QTRY_VERIFY_WITH_TIMEOUT(!timeline.isPlaying(), 3000);
        QCOMPARE(framesVisited(changes), QList<int>({1, 2, 3}));

        timeline.setCachedFrames({});
        timeline.play();
        QVERIFY2(!timeline.isPlaying(), "nothing cached: nothing to play");
    }

    void loopWrapsToTheFirstCachedFrame() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 8);
        timeline.setCachedFrames({1, 2, 3});
        timeline.setFps(100.0);
        timeline.setLoop(true);
        QSignalSpy changes(&timeline, &TimelineWidget::currentFrameChanged);
        QSignalSpy playing(&timeline, &TimelineWidget::playingChanged);
        timeline.togglePlayback();
        QTRY_VERIFY_WITH_TIMEOUT(changes.count() >= 5, 3000);
        QVERIFY(timeline.isPlaying());
        timeline.togglePlayback();
        QVERIFY(!timeline.isPlaying());
        QCOMPARE(framesVisited(changes).mid(0, 5), QList<int>({2, 3, 1, 2, 3}));
        QCOMPARE(playing.count(), 2);
    }

    void theLoopButtonShowsItsState() {
        TimelineWidget timeline;
        auto* loop = timeline.findChild<QToolButton*>(QStringLiteral("loopButton"));
        QVERIFY(!loop->isChecked());
        QVERIFY(!loop->autoRaise()); // a raised, pressed-in look while on
        QVERIFY(loop->toolTip().startsWith(QStringLiteral("Loop playback: off")));
        loop->click();
        QVERIFY(timeline.loops());
        QVERIFY(loop->isChecked());
        QVERIFY(loop->toolTip().startsWith(QStringLiteral("Loop playback: on")));
        timeline.setLoop(false);
        QVERIFY(!loop->isChecked());
        QVERIFY(loop->toolTip().startsWith(QStringLiteral("Loop playback: off")));
    }

    void theRateIsTheScenesOrEveryFrame() {
        TimelineWidget timeline;
        timeline.setFps(24.0);
        auto* choice = timeline.findChild<QComboBox*>(QStringLiteral("playbackRateChoice"));
        QCOMPARE(choice->count(), 2);
        QCOMPARE(choice->itemText(0), QStringLiteral("24 fps"));
        QCOMPARE(choice->itemText(1), QStringLiteral("Every frame"));
        QCOMPARE(timeline.playbackRate(), TimelineWidget::PlaybackRate::SceneFps);
        choice->setCurrentIndex(1);
        Q_EMIT choice->activated(1);
        QCOMPARE(timeline.playbackRate(), TimelineWidget::PlaybackRate::EveryFrame);
    }

    void everyFrameWaitsForTheViewportToShowEachFrame() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 8);
        timeline.setCachedFrames({1, 2, 3, 4});
        timeline.setPlaybackRate(TimelineWidget::PlaybackRate::EveryFrame);
        timeline.play();
        QTRY_COMPARE_WITH_TIMEOUT(timeline.currentFrame(), 2, 1000);
        QTest::qWait(150);
        QCOMPARE(timeline.currentFrame(), 2); // not shown yet: no frame is skipped
        timeline.frameDisplayed(2);
        QTRY_COMPARE_WITH_TIMEOUT(timeline.currentFrame(), 3, 1000);
        timeline.frameDisplayed(3);
        QTRY_COMPARE_WITH_TIMEOUT(timeline.currentFrame(), 4, 1000);
        // A frame that never shows (its load failed) holds playback half a second at most.
        QTRY_VERIFY_WITH_TIMEOUT(!timeline.isPlaying(), 2000);
    }

    void theAchievedRateIsShown() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 100);
        QList<int> all;
        for (int frame = 1; frame <= 100; ++frame)
            all << frame;
        timeline.setCachedFrames(all);
        timeline.setFps(20.0);
        // A viewport that shows every frame at once.
        connect(&timeline, &TimelineWidget::currentFrameChanged, &timeline,
                &TimelineWidget::frameDisplayed);
        timeline.play();
        QTRY_VERIFY_WITH_TIMEOUT(timeline.currentFrame() >= 16, 5000);
        // 20 fps asked for; timers on a loaded machine run late, never early.
        QVERIFY2(timeline.achievedFps() > 8.0 && timeline.achievedFps() < 22.0,
                 qPrintable(QString::number(timeline.achievedFps())));
        auto* label = timeline.findChild<QLabel*>(QStringLiteral("achievedFpsLabel"));
        QCOMPARE(label->text(), QStringLiteral("%1 fps").arg(timeline.achievedFps(), 0, 'f', 1));
    }

    void renderOutputFramesAreMarked() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 8);
        timeline.setRenderOutputFrames({1, 2, 3});
        QCOMPARE(timeline.renderOutputFrames(), (QList<int>{1, 2, 3}));
    }

    void playbackFollowsARunningBake() {
        TimelineWidget timeline;
        timeline.setFrameRange(1, 8);
        timeline.setCachedFrames({1, 2});
        timeline.setFps(100.0);
        timeline.setBakeRunning(true);
        timeline.play();
        QTRY_COMPARE_WITH_TIMEOUT(timeline.currentFrame(), 2, 3000);
        QTest::qWait(100);
        QVERIFY2(timeline.isPlaying(), "waits for the bake's next frame");
        timeline.addCachedFrame(3);
        QTRY_COMPARE_WITH_TIMEOUT(timeline.currentFrame(), 3, 3000);
        timeline.setBakeRunning(false);
        QTRY_VERIFY_WITH_TIMEOUT(!timeline.isPlaying(), 3000);
        QCOMPARE(timeline.currentFrame(), 3);
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestTimeline)
#include "TestTimeline.moc"
