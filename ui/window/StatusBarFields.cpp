#include "window/StatusBarFields.h"

#include "bake/BakeProgress.h"
#include "cache/FrameFile.h"
#include "sim/SimulationState.h"

#include <QLabel>
#include <QLocale>
#include <QProgressBar>
#include <QStatusBar>
#include <QStringList>
#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

constexpr int kBarSteps = 1000;

} // namespace

StatusBarFields::StatusBarFields(QStatusBar* statusBar) : QObject(statusBar) {
    frame_ = addField(statusBar, "frameField", tr("Frame shown in the viewport"));
    time_ = addField(statusBar, "timeField", tr("Simulated time of that frame"));
    particles_ = addField(statusBar, "particlesField", tr("Water particles in that frame"));
    bubbles_ = addField(statusBar, "bubblesField",
                        tr("Trapped air bubbles: alive in that frame, created and deleted up to "
                           "it, with the deletions per rule"));
    bubbles_->hide();
    progress_ = new QProgressBar(statusBar);
    progress_->setObjectName(QStringLiteral("bakeProgressBar"));
    progress_->setToolTip(tr("The bake: frames done of the scene's range, with the share of the "
                             "frame being computed"));
    // Per mille, so the current frame's share moves the bar even in a range of many frames.
    progress_->setRange(0, kBarSteps);
    progress_->setMinimumWidth(220);
    progress_->hide();
    statusBar->addPermanentWidget(progress_);
    step_ = addField(statusBar, "stepField", tr("Wall time per simulation step of the bake"));
    eta_ = addField(statusBar, "etaField", tr("Estimated time until the bake finishes"));
}

QLabel* StatusBarFields::addField(QStatusBar* statusBar, const char* objectName,
                                  const QString& toolTip) {
    auto* field = new QLabel(statusBar);
    field->setObjectName(QLatin1String(objectName));
    field->setToolTip(toolTip);
    field->setMinimumWidth(90);
    statusBar->addPermanentWidget(field);
    return field;
}

void StatusBarFields::showFrame(int frame, const FrameData& data) {
    frame_->setText(tr("Frame %1").arg(frame));
    time_->setText(tr("t = %1 s").arg(data.state.time, 0, 'f', 3));
    particles_->setText(
        tr("%1 particles").arg(QLocale().toString(qulonglong(data.state.fluid.size()))));
    showBubbles(bubbleSummary(data.state));
}

void StatusBarFields::showFrameNumber(int frame, double fps) {
    frame_->setText(tr("Frame %1").arg(frame));
    time_->setText(tr("t = %1 s").arg((frame - 1) / fps, 0, 'f', 3));
    particles_->clear();
    showBubbles(QString());
}

void StatusBarFields::showBubbles(const QString& summary) {
    // Hidden rather than "0 bubbles": most scenes have none, and the bar has little room.
    bubbles_->setText(summary);
    bubbles_->setVisible(!summary.isEmpty());
}

QString StatusBarFields::bubbleSummary(const SimulationState& state) {
    const BubbleTally& deleted = state.bubblesDeleted;
    if (state.nextBubbleId == 0 && deleted.deletedTotal() == 0)
        return QString();
    const QLocale locale;
    QStringList perRule;
    for (int rule = 0; rule < BubbleTally::RuleCount; ++rule) {
        const std::string_view name = BubbleTally::kRuleNames[rule];
        perRule << QStringLiteral("%1 %2").arg(
            QString::fromUtf8(name.data(), qsizetype(name.size())),
            locale.toString(qulonglong(deleted.deleted[rule])));
    }
    return tr("Bubbles %1 · created %2 · deleted %3 (%4)")
        .arg(locale.toString(qulonglong(state.bubbles.size())),
             locale.toString(qulonglong(state.nextBubbleId)),
             locale.toString(qulonglong(deleted.deletedTotal())),
             perRule.join(QStringLiteral(", ")));
}

void StatusBarFields::showBakeProgress(const BakeProgress& progress, double fraction,
                                       double etaSeconds) {
    showBakeBar(tr("Frame %1 of %2").arg(progress.frame).arg(progress.lastFrame), fraction);
    if (progress.stepsPerSecond > 0.0)
        step_->setText(tr("%1 ms/step").arg(1000.0 / progress.stepsPerSecond, 0, 'f', 1));
    eta_->setText(etaSeconds >= 0.0 ? tr("ETA %1").arg(duration(etaSeconds)) : tr("ETA …"));
}

void StatusBarFields::showBakePaused(int frame, int lastFrame, double fraction) {
    // Paused before the first step's report: no frame to name yet.
    showBakeBar(lastFrame > 0 ? tr("Paused · frame %1 of %2").arg(frame).arg(lastFrame)
                              : tr("Paused"),
                fraction);
    eta_->setText(tr("Paused"));
}

void StatusBarFields::showBakeBar(const QString& text, double fraction) {
    const int steps = int(std::floor(std::clamp(fraction, 0.0, 1.0) * kBarSteps));
    progress_->setValue(steps);
    // Whole per cents rounded down: 100 % only when the last frame is done. QProgressBar would
    // read "%p" in the text as its own placeholder, so the number is written out here.
    progress_->setFormat(QStringLiteral("%1 · %2 %").arg(text).arg(steps * 100 / kBarSteps));
    progress_->show();
}

void StatusBarFields::clearBake() {
    progress_->hide();
    progress_->reset();
    step_->clear();
    eta_->clear();
}

QString StatusBarFields::duration(double seconds) {
    const long long whole = std::llround(seconds);
    if (whole < 60)
        return tr("%1 s").arg(whole);
    if (whole < 3600)
        return tr("%1 min %2 s").arg(whole / 60).arg(whole % 60);
    return tr("%1 h %2 min").arg(whole / 3600).arg((whole % 3600) / 60);
}

} // namespace airtrap
