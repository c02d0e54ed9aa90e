// The status bar's permanent fields for a shown frame: the bubble field counts the frame's
// alive bubbles, those created so far and those deleted per rule, and stays out of the way for
// scenes that never had a bubble and in edit mode.
#include "cache/FrameFile.h"
#include "support/WidgetTestMain.h"
#include "window/StatusBarFields.h"

#include <QLabel>
#include <QStatusBar>
#include <QTest>
#include <array>

namespace airtrap {

namespace {

//! A frame at the end of which `alive` bubbles exist, `created` have been made so far and
//! `deleted` (age, floating, overlap, impact, surfaced) have gone.
FrameData frameWithBubbles(int alive, std::uint32_t created,
                           const std::array<std::uint64_t, BubbleTally::RuleCount>& deleted) {
    FrameData frame;
    frame.state.frame = 12;
    frame.state.time = 0.5;
    for (int i = 0; i < alive; ++i) {
        BubbleState bubble;
        bubble.id = created - std::uint32_t(alive) + std::uint32_t(i);
        bubble.radius = 0.01;
        frame.state.bubbles.push_back(bubble);
    }
    frame.state.nextBubbleId = created;
    frame.state.bubblesDeleted.deleted = deleted;
    return frame;
}

} // namespace

class TestStatusBarFields : public QObject {
    Q_OBJECT

private Q_SLOTS:
    void aFrameWithBubblesShowsTheCountsPerRule() {
        QStatusBar bar;
        StatusBarFields fields(&bar);
        QVERIFY(fields.bubblesField()->isHidden());

        fields.showFrame(12, frameWithBubbles(12, 37, {2, 10, 5, 1, 7}));
        QCOMPARE(fields.bubblesField()->text(),
                 QStringLiteral("Bubbles 12 · created 37 · deleted 25 "
                                "(age 2, floating 10, overlap 5, impact 1, surfaced 7)"));
        QVERIFY(!fields.bubblesField()->isHidden());
        QCOMPARE(fields.frameField()->text(), QStringLiteral("Frame 12"));
    }

    void bubblesThatAreAllGoneStillShow() {
        QStatusBar bar;
        StatusBarFields fields(&bar);
        fields.showFrame(40, frameWithBubbles(0, 3, {0, 3, 0, 0, 0}));
        QCOMPARE(fields.bubblesField()->text(),
                 QStringLiteral("Bubbles 0 · created 3 · deleted 3 "
                                "(age 0, floating 3, overlap 0, impact 0, surfaced 0)"));
        QVERIFY(!fields.bubblesField()->isHidden());
    }

    void aSceneWithoutBubblesHidesTheField() {
        QStatusBar bar;
        StatusBarFields fields(&bar);
        fields.showFrame(12, frameWithBubbles(2, 2, {0, 0, 0, 0}));
        QVERIFY(!fields.bubblesField()->isHidden());

        fields.showFrame(12, frameWithBubbles(0, 0, {0, 0, 0, 0}));
        QVERIFY(fields.bubblesField()->isHidden());
        QVERIFY(fields.bubblesField()->text().isEmpty());
        QVERIFY(StatusBarFields::bubbleSummary(FrameData{}.state).isEmpty());
    }

    void editModeHidesTheField() {
        QStatusBar bar;
        StatusBarFields fields(&bar);
        fields.showFrame(12, frameWithBubbles(1, 1, {0, 0, 0, 0}));
        fields.showFrameNumber(13, 30.0);
        QVERIFY(fields.bubblesField()->isHidden());
        QCOMPARE(fields.frameField()->text(), QStringLiteral("Frame 13"));
    }
};

} // namespace airtrap

AIRTRAP_TEST_WIDGETS(airtrap::TestStatusBarFields)
#include "TestStatusBarFields.moc"
