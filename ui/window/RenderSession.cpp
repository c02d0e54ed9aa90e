#include "window/RenderSession.h"

#include "controller/RenderOutputController.h"
#include "document/SceneDocument.h"
#include "window/EditorActions.h"
#include "window/ExportDialog.h"
#include "window/LogPanel.h"

#include <QAction>
#include <QDir>
#include <QProgressBar>
#include <QStatusBar>
#include <QToolButton>
#include <cmath>

namespace airtrap {

RenderSession::RenderSession(SceneDocument& document, RenderOutputController& controller,
                             LogPanel& log, EditorActions& actions, QStatusBar& statusBar,
                             QWidget* dialogParent)
    : QObject(dialogParent), document_(document), controller_(controller), log_(log),
      actions_(actions), dialogParent_(dialogParent), progressBar_(new QProgressBar),
      cancelButton_(new QToolButton) {
    progressBar_->setObjectName(QStringLiteral("renderProgress"));
    progressBar_->setRange(0, 100);
    progressBar_->setMaximumWidth(220);
    progressBar_->setTextVisible(true);
    cancelButton_->setDefaultAction(actions_.cancelRenderOutputs);
    statusBar.addPermanentWidget(progressBar_);
    statusBar.addPermanentWidget(cancelButton_);
    progressBar_->hide();
    cancelButton_->hide();
    connect(actions_.post, &QAction::triggered, this, &RenderSession::post);
    connect(actions_.exportSequences, &QAction::triggered, this, &RenderSession::exportSequences);
    connect(actions_.cancelRenderOutputs, &QAction::triggered, &controller_,
            &RenderOutputController::cancel);
    connect(&controller_, &RenderOutputController::progress, this, &RenderSession::onProgress);
    connect(&controller_, &RenderOutputController::finished, this, &RenderSession::onFinished);
    connect(&controller_, &RenderOutputController::failed, this, &RenderSession::onFailed);
    connect(&controller_, &RenderOutputController::busyChanged, this, [this](bool busy) {
        progressBar_->setVisible(busy);
        cancelButton_->setVisible(busy);
        progressBar_->setValue(0);
        updateActions();
    });
    updateActions();
}

void RenderSession::setCacheDirectoryProvider(std::function<QString()> provider) {
    cacheDirectory_ = std::move(provider);
}

void RenderSession::setLastCachedFrameProvider(std::function<int()> provider) {
    lastCachedFrame_ = std::move(provider);
    updateActions();
}

void RenderSession::updateActions() {
    const bool ready = !controller_.isBusy() && lastCachedFrame_() > 0;
    actions_.post->setEnabled(ready);
    actions_.exportSequences->setEnabled(ready);
    actions_.cancelRenderOutputs->setEnabled(controller_.isBusy());
}

void RenderSession::post() {
    run(RenderRequest{});
}

void RenderSession::exportSequences() {
    const QString cache = cacheDirectory_ ? cacheDirectory_() : QString();
    ExportDialog dialog(lastCachedFrame_(), QDir(cache).filePath(QStringLiteral("export")),
                        dialogParent_);
    if (dialog.exec() == QDialog::Accepted)
        run(dialog.request());
}

void RenderSession::run(RenderRequest request) {
    if (controller_.isBusy() || !cacheDirectory_)
        return;
    request.cacheDir = cacheDirectory_().toStdString();
    request.surfaceMesh = document_.scene().surfaceMesh;
    request.bubbleMesh = document_.scene().bubbleMesh;
    request.subgridBubbles = document_.scene().subgridBubbles;
    log_.info(request.formats.empty()
                  ? tr("Making render outputs of %1").arg(QString::fromStdString(request.cacheDir))
                  : tr("Exporting %1 into %2")
                        .arg(QString::fromStdString(request.cacheDir),
                             QString::fromStdString(request.outDir)));
    controller_.start(request);
}

void RenderSession::onProgress(const QString& stage, double percent) {
    progressBar_->setFormat(stage + QStringLiteral(" %p%"));
    progressBar_->setValue(int(std::lround(percent)));
}

void RenderSession::onFinished(bool completed, const QString& summary) {
    if (completed)
        log_.info(summary);
    else
        log_.warning(tr("Render outputs stopped: %1").arg(summary));
    Q_EMIT statusMessage(completed ? tr("Render outputs done") : tr("Render outputs stopped"));
    Q_EMIT outputsChanged();
}

void RenderSession::onFailed(const QString& message) {
    log_.error(message);
    Q_EMIT statusMessage(tr("Render outputs failed: %1").arg(message));
    Q_EMIT outputsChanged();
}

} // namespace airtrap
