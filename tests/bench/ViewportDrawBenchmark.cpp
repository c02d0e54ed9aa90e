#include "ViewportDrawBenchmark.h"

#include "viewport/ViewportWidget.h"

#include <QCoreApplication>
#include <QElapsedTimer>
#include <QEventLoop>
#include <QMouseEvent>
#include <QOpenGLContext>
#include <QOpenGLFunctions>
#include <QTimer>
#include <QWindow>
#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <vector>

namespace airtrap::bench {

namespace {

constexpr int kExposeTimeoutMs = 10000;
//! Longest a frame may take to reach the screen before the benchmark gives up on it.
constexpr int kFrameTimeoutMs = 60000;
//! Longer than the 5 ms by which Qt on xcb paces update requests, short enough not to add up.
constexpr int kSettleMs = 10;
//! Pixels the cursor moves per measured frame: 0.8° of orbit, enough that no frame repeats.
constexpr int kDragPixelsPerFrame = 2;

double median(std::vector<double> values) {
    if (values.empty()) {
        return 0.0;
    }
    const auto middle = values.begin() + std::ptrdiff_t(values.size() / 2);
    std::nth_element(values.begin(), middle, values.end());
    return *middle;
}

} // namespace

ViewportDrawBenchmark::ViewportDrawBenchmark(const QSize& size)
    : viewport_(std::make_unique<ViewportWidget>()) {
    QObject::connect(viewport_.get(), &QOpenGLWidget::frameSwapped, [this] { ++framesSwapped_; });
    viewport_->resize(size);
    viewport_->show();
    if (!waitUntilPainted()) {
        openGlProblem_ = QStringLiteral("the viewport got no OpenGL context (is X running?)");
        return;
    }
    const QSurfaceFormat format = viewport_->context()->format();
    if (format.version() < qMakePair(3, 3) || format.profile() != QSurfaceFormat::CoreProfile) {
        openGlProblem_ =
            QStringLiteral("the viewport needs OpenGL 3.3 core, got %1.%2%3")
                .arg(format.majorVersion())
                .arg(format.minorVersion())
                .arg(format.profile() == QSurfaceFormat::CoreProfile ? QStringLiteral(" core")
                                                                     : QStringLiteral(""));
        return;
    }
    viewport_->makeCurrent();
    const auto* name = viewport_->context()->functions()->glGetString(GL_RENDERER);
    renderer_ = name ? QString::fromLatin1(reinterpret_cast<const char*>(name)) : QString();
    viewport_->doneCurrent();
}

ViewportDrawBenchmark::~ViewportDrawBenchmark() = default;

QSize ViewportDrawBenchmark::viewportSize() const {
    return viewport_->size();
}

bool ViewportDrawBenchmark::waitUntilPainted() {
    // QOpenGLWidget creates its context on the first paint after the window is exposed, so the
    // window being exposed is not enough: wait for isValid() too.
    QElapsedTimer timer;
    timer.start();
    while (timer.elapsed() < kExposeTimeoutMs) {
        settle();
        const QWindow* window = viewport_->windowHandle();
        if (window && window->isExposed() && viewport_->isValid()) {
            return true;
        }
    }
    return false;
}

void ViewportDrawBenchmark::finishGl() {
    viewport_->makeCurrent();
    viewport_->context()->functions()->glFinish();
    viewport_->doneCurrent();
}

void ViewportDrawBenchmark::settle() {
    QEventLoop loop;
    QTimer::singleShot(kSettleMs, &loop, &QEventLoop::quit);
    loop.exec();
}

double ViewportDrawBenchmark::timedFrame(const std::function<void()>& change) {
    settle();
    finishGl(); // nothing of earlier frames may still be running when the clock starts
    const int swappedBefore = framesSwapped_;
    using Clock = std::chrono::steady_clock;
    const Clock::time_point start = Clock::now();
    change();
    // repaint() usually paints and composites before it returns, but Qt may defer it to the
    // window's next update request (seen with small windows): the frame is waited for, so that a
    // deferred paint never counts as an instant one.
    viewport_->repaint();
    QElapsedTimer timeout;
    timeout.start();
    while (framesSwapped_ == swappedBefore) {
        if (timeout.elapsed() > kFrameTimeoutMs) {
            throw std::runtime_error("the viewport did not put a frame on screen");
        }
        QCoreApplication::processEvents(QEventLoop::WaitForMoreEvents);
    }
    // The swap may return before a threaded rasteriser (llvmpipe) is done with the frame.
    finishGl();
    return std::chrono::duration<double, std::milli>(Clock::now() - start).count();
}

void ViewportDrawBenchmark::pressMouse() {
    dragX_ = viewport_->width() / 2;
    const QPointF at(dragX_, viewport_->height() / 2);
    QMouseEvent press(QEvent::MouseButtonPress, at, viewport_->mapToGlobal(at), Qt::LeftButton,
                      Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport_.get(), &press);
    // Past the click slop at once, so that every later step turns the camera.
    dragBy(int(DragTracker::kClickSlop) + 1);
}

void ViewportDrawBenchmark::dragBy(int pixels) {
    dragX_ += pixels;
    const QPointF at(dragX_, viewport_->height() / 2);
    QMouseEvent move(QEvent::MouseMove, at, viewport_->mapToGlobal(at), Qt::NoButton,
                     Qt::LeftButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport_.get(), &move);
}

void ViewportDrawBenchmark::releaseMouse() {
    const QPointF at(dragX_, viewport_->height() / 2);
    QMouseEvent release(QEvent::MouseButtonRelease, at, viewport_->mapToGlobal(at), Qt::LeftButton,
                        Qt::NoButton, Qt::NoModifier);
    QCoreApplication::sendEvent(viewport_.get(), &release);
}

ViewportDrawResult ViewportDrawBenchmark::run(const Scene& scene,
                                              const std::shared_ptr<const FrameData>& frame,
                                              int uploads, int frames, int warmupFrames) {
    ViewportDrawResult result;
    result.particles = frame ? frame->state.fluid.size() : 0;
    viewport_->setScene(scene);
    viewport_->frameAll(); // every particle count starts from the same view

    // The first upload at a new size allocates the buffer; later frames of a playback reuse it,
    // so that one is not measured. setFrame() recomputes the speeds and marks the buffer for
    // upload, which the next paint does.
    timedFrame([&] { viewport_->setFrame(frame); });
    std::vector<double> uploadTimes;
    for (int i = 0; i < uploads; ++i) {
        uploadTimes.push_back(timedFrame([&] { viewport_->setFrame(frame); }));
    }
    result.uploadMilliseconds = median(uploadTimes);

    std::vector<double> drawTimes;
    pressMouse();
    for (int i = 0; i < warmupFrames + frames; ++i) {
        const double ms = timedFrame([&] { dragBy(kDragPixelsPerFrame); });
        if (i >= warmupFrames) {
            drawTimes.push_back(ms);
        }
    }
    releaseMouse();
    settle();
    result.drawMilliseconds = median(drawTimes);
    result.framesPerSecond = result.drawMilliseconds > 0.0 ? 1000.0 / result.drawMilliseconds : 0.0;
    return result;
}

} // namespace airtrap::bench
