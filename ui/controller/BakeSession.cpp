#include "controller/BakeSession.h"

#include "controller/FrameLoader.h"
#include "controller/SimulationController.h"
#include "core/Error.h"
#include "document/SceneDocument.h"
#include "sim/SceneCheck.h"
#include "timeline/TimelineWidget.h"
#include "window/EditorActions.h"
#include "window/EditorSettings.h"
#include "window/LogPanel.h"
#include "window/StatusBarFields.h"

#include <QAction>
#include <QFileInfo>
#include <QMessageBox>
#include <QPushButton>
#include <QTimer>
#include <utility>

namespace airtrap {

namespace {
//! Discarding needs the bake thread gone; a step of a large scene can take seconds.
constexpr int kStopTimeoutMs = 60000;
//! The editor's settings key listing the cache folders it made.
constexpr auto kMadeFoldersKey = "cache/madeFolders";
} // namespace

BakeSession::BakeSession(SceneDocument& document, SimulationController& controller,
                         TimelineWidget& timeline, FrameLoader& loader, LogPanel& log,
                         StatusBarFields& statusFields, EditorActions& actions,
                         QWidget* dialogParent)
    : QObject(dialogParent), document_(document), controller_(controller), timeline_(timeline),
      loader_(loader), log_(log), statusFields_(statusFields), actions_(actions),
      dialogParent_(dialogParent) {
    connectActions();
    connectController();
    connect(&loader_, &FrameLoader::framesListed, this, &BakeSession::onFramesListed);
    updateActions();
}

void BakeSession::setCacheDirectoryProvider(std::function<QString()> provider) {
    cacheDirectory_ = std::move(provider);
}

void BakeSession::setBakeDirectoryProvider(std::function<QString()> provider) {
    bakeDirectory_ = std::move(provider);
}

void BakeSession::connectActions() {
    connect(actions_.bake, &QAction::triggered, this, &BakeSession::bake);
    connect(actions_.resume, &QAction::triggered, this, &BakeSession::resumeBake);
    connect(actions_.pause, &QAction::triggered, &controller_, &SimulationController::pause);
    connect(actions_.stop, &QAction::triggered, &controller_, &SimulationController::stop);
    connect(actions_.clearCache, &QAction::triggered, this, &BakeSession::clearCache);
}

void BakeSession::connectController() {
    connect(&controller_, &SimulationController::stateChanged, this, &BakeSession::onStateChanged);
    connect(&controller_, &SimulationController::progress, this, &BakeSession::onProgress);
    connect(&controller_, &SimulationController::frameFinished, this,
            [this](int frame) { onFrameFinished(frame); });
    connect(&controller_, &SimulationController::message, &log_, &LogPanel::info);
    connect(&controller_, &SimulationController::finished, this, &BakeSession::onFinished);
    connect(&controller_, &SimulationController::failed, this, &BakeSession::onFailed);
}

// --- Actions ------------------------------------------------------------------------------------

void BakeSession::bake() {
    if (controller_.isBusy() || !acceptOverlaps())
        return;
    const QString dir = bakeDirectory_ ? bakeDirectory_() : cacheDirectory_();
    if (dir.isEmpty())
        return;
    if (lastCachedFrame() > 1 &&
        !confirm(
            tr("Bake"),
            tr("Replace the %1 cached frames in %2 with a new bake?").arg(cached_.size()).arg(dir),
            true))
        return;
    cached_.clear();
    timeline_.setCachedFrames({});
    staleFramesAccepted_ = false;
    // A fresh bake rewrites the folder: the loader must forget the frames it kept from it.
    loader_.setCacheDirectory(dir);
    log_.info(tr("Baking %1 into %2").arg(document_.displayName(), dir));
    if (!QFileInfo::exists(dir))
        rememberMadeFolder(dir);
    startMeter();
    controller_.bake(document_.scene(), dir, false);
}

void BakeSession::resumeBake() {
    if (controller_.state() == SimulationController::State::Paused) {
        controller_.resume();
        return;
    }
    if (controller_.isBusy())
        return;
    staleFramesAccepted_ = false;
    log_.info(
        tr("Resuming the bake from frame %1 in %2").arg(lastCachedFrame()).arg(cacheDirectory_()));
    startMeter();
    controller_.bake(document_.scene(), cacheDirectory_(), true);
}

void BakeSession::clearCache() {
    if (controller_.isBusy() || cached_.empty())
        return;
    const QString dir = cacheDirectory_();
    if (!madeFolder(dir)) {
        if (confirm(tr("Clear Cache"),
                    tr("Delete all %1 cached frames of this scene?").arg(cached_.size()), true))
            discardFramesAfter(0);
        return;
    }
    if (!confirm(tr("Clear Cache"),
                 tr("Delete all %1 cached frames of this scene, their render outputs and the "
                    "folder %2 made for them?")
                     .arg(cached_.size())
                     .arg(dir),
                 true))
        return;
    removeMadeCache(dir);
}

void BakeSession::removeMadeCache(const QString& dir) {
    if (controller_.removeCache(dir)) {
        forgetMadeFolder(dir);
        log_.info(tr("Cleared the cache and removed its folder %1").arg(dir));
    } else if (QFileInfo::exists(dir)) {
        log_.info(tr("Cleared the cache; kept its folder %1, which holds other files").arg(dir));
    }
    loader_.refresh();
}

// --- Folders the editor made ---------------------------------------------------------------------

void BakeSession::rememberMadeFolder(const QString& dir) {
    QSettings& settings = EditorSettings::store();
    QStringList folders = settings.value(QLatin1String(kMadeFoldersKey)).toStringList();
    // Folders deleted since (by hand, or by another editor) are forgotten, so the list stays as
    // short as the caches that exist.
    folders.removeIf([](const QString& folder) { return !QFileInfo::exists(folder); });
    const QString path = QFileInfo(dir).absoluteFilePath();
    if (!folders.contains(path))
        folders << path;
    settings.setValue(QLatin1String(kMadeFoldersKey), folders);
}

bool BakeSession::madeFolder(const QString& dir) {
    return EditorSettings::store()
        .value(QLatin1String(kMadeFoldersKey))
        .toStringList()
        .contains(QFileInfo(dir).absoluteFilePath());
}

void BakeSession::forgetMadeFolder(const QString& dir) {
    QSettings& settings = EditorSettings::store();
    QStringList folders = settings.value(QLatin1String(kMadeFoldersKey)).toStringList();
    folders.removeAll(QFileInfo(dir).absoluteFilePath());
    settings.setValue(QLatin1String(kMadeFoldersKey), folders);
}

bool BakeSession::releaseCache() {
    if (!controller_.isBusy())
        return true;
    if (!confirm(tr("Bake running"),
                 tr("A bake is running. Stop it? The frames it finished stay in the cache."), true))
        return false;
    controller_.stop();
    controller_.waitForIdle(kStopTimeoutMs);
    return true;
}

void BakeSession::cacheFolderChanged() {
    cached_.clear();
    timeline_.setCachedFrames({});
    staleFramesAccepted_ = false;
    loader_.setCacheDirectory(cacheDirectory_());
    updateActions();
}

// --- Edits while frames exist -------------------------------------------------------------------

void BakeSession::sceneEdited() {
    if (staleQuestionPending_ || staleFramesAccepted_)
        return;
    if (!controller_.isBusy() && lastCachedFrame() <= timeline_.currentFrame())
        return;
    // Asked from the event loop, not inside the edit: the edit may be one step of a slider drag.
    staleQuestionPending_ = true;
    QTimer::singleShot(0, this, &BakeSession::askAboutStaleFrames);
}

void BakeSession::askAboutStaleFrames() {
    staleQuestionPending_ = false;
    const int keep = std::max(1, timeline_.currentFrame());
    const bool discard =
        confirm(tr("Scene changed"),
                tr("The frames after frame %1 were baked with the old settings. Discard them?\n\n"
                   "Frames 1–%1 stay; Resume then continues from frame %1 with the new settings.")
                    .arg(keep),
                false);
    if (!discard) {
        staleFramesAccepted_ = true;
        log_.warning(tr("Kept cached frames that were baked with the previous settings"));
        return;
    }
    discardFramesAfter(keep);
}

void BakeSession::discardFramesAfter(int frame) {
    if (controller_.isBusy()) {
        controller_.stop();
        controller_.waitForIdle(kStopTimeoutMs);
    }
    controller_.discardFramesAfter(cacheDirectory_(), frame);
    log_.info(frame > 0 ? tr("Discarded the frames after frame %1").arg(frame)
                        : tr("Cleared the cache"));
    loader_.refresh();
}

// --- Controller and loader reports --------------------------------------------------------------

void BakeSession::onFrameFinished(int frame) {
    // Follow the bake while the user watches its newest frame; leave them alone otherwise.
    const bool following = !timeline_.isPlaying() && timeline_.currentFrame() == lastCachedFrame();
    cached_.insert(frame);
    timeline_.addCachedFrame(frame);
    loader_.refresh();
    updateActions();
    if (following)
        timeline_.setCurrentFrame(frame);
}

void BakeSession::onFramesListed(const QList<int>& frames) {
    cached_ = std::set<int>(frames.begin(), frames.end());
    timeline_.setCachedFrames(frames);
    updateActions();
    Q_EMIT cachedFramesChanged();
}

void BakeSession::onProgress(const BakeProgress& progress) {
    const double fraction = meter_.update(progress);
    // The bar has the frame and the share; the status message is left to events worth reading.
    if (meter_.isPaused())
        statusFields_.showBakePaused(meter_.frame(), meter_.lastFrame(), fraction);
    else
        statusFields_.showBakeProgress(progress, fraction, meter_.etaSeconds(secondsNow()));
}

void BakeSession::onStateChanged(SimulationController::State state) {
    using State = SimulationController::State;
    const State before = std::exchange(lastState_, state);
    timeline_.setBakeRunning(state != State::Idle);
    updateActions();
    const int percent = int(meter_.fraction() * 100.0);
    if (state == State::Paused) {
        meter_.pause(secondsNow());
        statusFields_.showBakePaused(meter_.frame(), meter_.lastFrame(), meter_.fraction());
        log_.info(tr("Bake paused at frame %1 (%2 %)").arg(meter_.frame()).arg(percent));
        Q_EMIT statusMessage(tr("Bake paused"));
    } else if (state == State::Running && before == State::Paused) {
        meter_.resume(secondsNow());
        log_.info(tr("Bake resumed at frame %1 (%2 %)").arg(meter_.frame()).arg(percent));
        Q_EMIT statusMessage(tr("Bake resumed"));
    }
}

void BakeSession::startMeter() {
    clock_.start();
    meter_.start(0.0);
}

double BakeSession::secondsNow() const {
    return clock_.isValid() ? double(clock_.nsecsElapsed()) * 1e-9 : 0.0;
}

void BakeSession::onFinished(bool completed, const QString& status) {
    statusFields_.clearBake();
    log_.info(completed ? tr("Bake complete") : tr("Bake %1").arg(status));
    Q_EMIT statusMessage(completed ? tr("Bake complete") : tr("Bake %1").arg(status));
    loader_.refresh();
}

void BakeSession::onFailed(const QString& message) {
    statusFields_.clearBake();
    log_.error(message);
    Q_EMIT statusMessage(tr("Bake failed"));
    loader_.refresh();
    if (interactive_)
        QMessageBox::critical(dialogParent_, tr("Bake failed"),
                              tr("%1\n\nEvery frame finished before this is kept.").arg(message));
}

void BakeSession::updateActions() {
    using State = SimulationController::State;
    const State state = controller_.state();
    const bool idle = state == State::Idle;
    actions_.bake->setEnabled(idle);
    actions_.pause->setEnabled(state == State::Running);
    actions_.resume->setEnabled(
        state == State::Paused ||
        (idle && lastCachedFrame() > 0 && lastCachedFrame() < document_.scene().frames.endFrame));
    actions_.stop->setEnabled(state == State::Running || state == State::Paused);
    actions_.clearCache->setEnabled(idle && !cached_.empty());
}

bool BakeSession::acceptOverlaps() {
    std::vector<std::string> warnings;
    try {
        warnings = validateScene(document_.scene());
    } catch (const Error&) {
        return true; // the bake fails at once with every error, in a dialog and the log
    }
    QStringList overlaps;
    for (const std::string& warning : warnings)
        if (warning.find("overlaps") != std::string::npos)
            overlaps << QString::fromStdString(warning);
    // Without a dialog the answer that loses nothing is to bake, as airtrap-cli does; the bake
    // writes every warning to the log itself.
    if (overlaps.isEmpty() || !interactive_)
        return true;
    QMessageBox box(QMessageBox::Warning, tr("Bodies overlap at the start"),
                    tr("At t = 0 these overlap:"), QMessageBox::NoButton, dialogParent_);
    box.setObjectName(QStringLiteral("overlapWarning"));
    box.setInformativeText(QStringLiteral("• ") + overlaps.join(QStringLiteral("\n\n• ")) +
                           tr("\n\nMove them apart, or bake anyway."));
    QPushButton* bakeAnyway = box.addButton(tr("Bake anyway"), QMessageBox::AcceptRole);
    bakeAnyway->setObjectName(QStringLiteral("bakeAnywayButton"));
    box.setDefaultButton(box.addButton(QMessageBox::Cancel));
    box.exec();
    if (box.clickedButton() == bakeAnyway)
        return true; // the bake logs the warnings as it starts
    for (const QString& overlap : overlaps)
        log_.warning(overlap);
    log_.info(tr("Bake cancelled: bodies overlap at t = 0"));
    Q_EMIT statusMessage(tr("Bake cancelled"));
    return false;
}

bool BakeSession::confirm(const QString& title, const QString& question, bool defaultAnswer) {
    if (!interactive_)
        return defaultAnswer;
    const auto answer =
        QMessageBox::question(dialogParent_, title, question, QMessageBox::Yes | QMessageBox::No,
                              defaultAnswer ? QMessageBox::Yes : QMessageBox::No);
    return answer == QMessageBox::Yes;
}

} // namespace airtrap
