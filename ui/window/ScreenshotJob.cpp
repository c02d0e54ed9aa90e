#include "window/ScreenshotJob.h"

#include "controller/FrameLoader.h"
#include "viewport/SurfaceShading.h"
#include "viewport/ViewportWidget.h"
#include "window/EditorActions.h"
#include "window/MainWindow.h"

#include <QAction>
#include <QActionGroup>
#include <QImage>
#include <QTimer>
#include <algorithm>

namespace airtrap {

namespace {
// Loading a large frame on a slow disk plus the first software-GL paint stay well within this.
constexpr int kTimeoutMs = 120000;
// The viewport repaints on the next frame after it receives data; give it a few.
constexpr int kSettleMs = 300;
} // namespace

ScreenshotJob::ScreenshotJob(MainWindow& window, ScreenshotRequest request, QObject* parent)
    : QObject(parent), window_(window), request_(std::move(request)), timeout_(new QTimer(this)) {
    timeout_->setSingleShot(true);
    connect(timeout_, &QTimer::timeout, this,
            [this] { fail(tr("timed out waiting for frame %1").arg(frameToShow_)); });
}

void ScreenshotJob::start() {
    window_.setInteractive(false);
    // Connected before anything opens: showing the window may run queued events, and the cache
    // listing must not slip past unheard.
    connect(&window_, &MainWindow::frameShown, this, [this](int frame) {
        if (frame == frameToShow_)
            QTimer::singleShot(kSettleMs, this, &ScreenshotJob::capture);
    });
    connect(window_.frameLoader(), &FrameLoader::loadFailed, this,
            [this](int frame, const QString& message) {
                if (frame == frameToShow_)
                    fail(message);
            });
    connect(&window_, &MainWindow::cachedFramesChanged, this, &ScreenshotJob::showRequestedFrame);
    if (!open())
        return;
    if (request_.wholeWindow)
        window_.resize(request_.size);
    else
        window_.viewport()->setFixedSize(request_.size);
    applyView();
    window_.show();
    timeout_->start(kTimeoutMs);
}

bool ScreenshotJob::open() {
    if (!request_.scenePath.isEmpty()) {
        if (!window_.openScene(request_.scenePath)) {
            fail(window_.lastError());
            return false;
        }
        if (!request_.cacheDir.isEmpty())
            window_.useCacheFolder(request_.cacheDir);
        return true;
    }
    if (request_.cacheDir.isEmpty()) {
        fail(tr("give --scene, --cache or both"));
        return false;
    }
    if (!window_.openCacheFolder(request_.cacheDir)) {
        fail(window_.lastError());
        return false;
    }
    return true;
}

void ScreenshotJob::applyView() {
    ViewportWidget& viewport = *window_.viewport();
    viewport.setShowSelection(false);
    viewport.setCameraView(request_.camera);
    viewport.setParticleSize(request_.particleSize);
    const EditorActions& actions = window_.actions();
    for (QAction* action : actions.surfaceShading->actions())
        if (surfaceShadingNamed(action->data().toString().toStdString()) == request_.surface)
            action->setChecked(true);
    if (!request_.layers)
        return;
    const ScreenshotRequest::Layers& show = *request_.layers;
    actions.showWater->setChecked(show.particles);
    actions.particlesUnderSurface->setChecked(show.particles);
    actions.showSurface->setChecked(show.mesh);
    viewport.setShowBubbles(show.bubbles);
    viewport.setShowSubgridBubbles(show.subgrid);
}

void ScreenshotJob::showRequestedFrame() {
    if (finished_ || frameToShow_ > 0)
        return;
    const std::vector<int> cached = window_.frameLoader()->cachedFrames();
    if (request_.frame <= 0) {
        // No frame asked for: what the editor shows on opening — frame 1 when it is cached, the
        // scene in edit mode when nothing is.
        if (cached.empty() || cached.front() != 1) {
            QTimer::singleShot(kSettleMs, this, &ScreenshotJob::capture);
            return;
        }
        frameToShow_ = 1;
    } else if (std::find(cached.begin(), cached.end(), request_.frame) == cached.end()) {
        fail(tr("frame %1 is not in the cache %2")
                 .arg(request_.frame)
                 .arg(window_.cacheDirectory()));
        return;
    } else {
        frameToShow_ = request_.frame;
    }
    window_.showFrame(frameToShow_);
}

void ScreenshotJob::capture() {
    if (finished_)
        return;
    const QImage image =
        request_.wholeWindow ? window_.grab().toImage() : window_.viewport()->grabFramebuffer();
    if (image.isNull() || !image.save(request_.outputPath, "PNG")) {
        fail(tr("cannot write %1").arg(request_.outputPath));
        return;
    }
    finished_ = true;
    timeout_->stop();
    Q_EMIT done(QString());
}

void ScreenshotJob::fail(const QString& error) {
    if (finished_)
        return;
    finished_ = true;
    timeout_->stop();
    Q_EMIT done(error);
}

} // namespace airtrap
