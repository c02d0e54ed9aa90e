#pragma once
// `airtrap --screenshot out.png`: open a scene (and its cache), show one frame, save the viewport
// (or the whole editor) as a PNG, and report — for the docs and for tests that look at pixels.
// What is drawn and from where comes from the request alone, never from the user's saved view
// options, and the selection is not drawn.
#include "viewport/ViewportWidget.h"

#include <QObject>
#include <QSize>
#include <QString>
#include <optional>

class QTimer;

namespace airtrap {

class MainWindow;

struct ScreenshotRequest {
    QString scenePath;  //!< empty: the scene comes from the cache's manifest
    QString cacheDir;   //!< empty: the folder next to the scene
    int frame = 0;      //!< 0: frame 1 when cached, else the scene in edit mode
    QString outputPath; //!< PNG
    QSize size{1280, 720};
    bool wholeWindow = false; //!< the editor window instead of the viewport alone

    //! What `--show` lists. Particles are drawn under a surface mesh only when listed.
    struct Layers {
        bool particles = false;
        bool mesh = false;
        bool bubbles = false;
        bool subgrid = false;
    };
    //! Unset: the editor's default view (a frame with a mesh shows the mesh, else particles).
    std::optional<Layers> layers;
    ViewportWidget::CameraView camera = ViewportWidget::CameraView::Perspective;
    SurfaceShading surface = SurfaceShading::Translucent;
    float particleSize = 1.0f; //!< times the default radius (half the particle spacing)
};

class ScreenshotJob : public QObject {
    Q_OBJECT

public:
    //! Takes over `window` (sets it non-interactive) until done.
    ScreenshotJob(MainWindow& window, ScreenshotRequest request, QObject* parent = nullptr);

    //! Opens, shows and waits for the frame; done() follows.
    void start();

Q_SIGNALS:
    //! `error` is empty on success, else what went wrong (file, frame, reason).
    void done(const QString& error);

private:
    bool open();
    //! The request's layers and camera, and no selection drawn.
    void applyView();
    void showRequestedFrame();
    void capture();
    void fail(const QString& error);

    MainWindow& window_;
    ScreenshotRequest request_;
    QTimer* timeout_;
    bool finished_ = false;
    //! The frame being loaded for the picture (0 until the cache listing arrived).
    int frameToShow_ = 0;
};

} // namespace airtrap
