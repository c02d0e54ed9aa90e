#pragma once
// Times the editor's real viewport widget, shown on screen, drawing one cached frame: the cost of
// taking a new frame (speeds, VBO upload and the paint that does it) and of a plain repaint while
// the camera turns. Every figure waits for the GPU (glFinish), so a driver that queues work
// cannot make a frame look cheaper than it is.
#include "cache/FrameFile.h"
#include "scene/Scene.h"

#include <QSize>
#include <QString>
#include <functional>
#include <memory>

namespace airtrap {

class ViewportWidget;

namespace bench {

//! Figures for one frame shown in the viewport.
struct ViewportDrawResult {
    std::size_t particles = 0;
    double uploadMilliseconds = 0.0; //!< median of setFrame + the paint that uploads it
    double drawMilliseconds = 0.0;   //!< median repaint with the camera moved since the last one
    double framesPerSecond = 0.0;    //!< 1000 / drawMilliseconds
};

class ViewportDrawBenchmark {
public:
    //! Shows a viewport of `size` widget pixels. A QApplication must exist, and the default
    //! surface format must be ViewportWidget::surfaceFormat() (set before the QApplication).
    explicit ViewportDrawBenchmark(const QSize& size);
    ~ViewportDrawBenchmark();
    ViewportDrawBenchmark(const ViewportDrawBenchmark&) = delete;
    ViewportDrawBenchmark& operator=(const ViewportDrawBenchmark&) = delete;

    //! Empty when the viewport got an OpenGL 3.3 core context; otherwise what went wrong.
    QString openGlProblem() const { return openGlProblem_; }
    //! GL_RENDERER of the viewport's context (e.g. "llvmpipe (LLVM 15.0.7, 256 bits)").
    QString renderer() const { return renderer_; }
    //! The viewport's size in widget pixels, as the window system granted it.
    QSize viewportSize() const;

    //! Shows `frame` of `scene` from the framed-all view, then times `uploads` uploads of it and
    //! `frames` repaints after `warmupFrames` unmeasured ones.
    ViewportDrawResult run(const Scene& scene, const std::shared_ptr<const FrameData>& frame,
                           int uploads, int frames, int warmupFrames);

private:
    //! Waits (handling events) until the widget is on screen and has painted once.
    bool waitUntilPainted();
    //! Handles events for a moment, outside any measurement, so that paints the widget asked for
    //! itself (update()) and Qt's pacing of window flushes are over before a clock starts.
    void settle();
    //! Settles, then makes `change`, repaints and waits until the frame is on screen and the GPU
    //! has finished; returns the milliseconds from the change to that.
    double timedFrame(const std::function<void()>& change);
    //! Ends the work queued on the viewport's context.
    void finishGl();
    //! A left-button drag step of `pixels` to the right: orbits the camera as a user would.
    void dragBy(int pixels);
    void pressMouse();
    void releaseMouse();

    std::unique_ptr<ViewportWidget> viewport_;
    QString openGlProblem_;
    QString renderer_;
    int dragX_ = 0;
    int framesSwapped_ = 0; //!< frames the viewport has put on screen so far
};

} // namespace bench
} // namespace airtrap
