#pragma once
// The editor's 3D view. For now it only proves that an OpenGL 3.3 core context comes up and clears;
// drawing the scene and the baked frames is a later step.
#include <QColor>
#include <QOpenGLWidget>
#include <QSurfaceFormat>

namespace airtrap {

class ViewportWidget : public QOpenGLWidget {
    Q_OBJECT

public:
    explicit ViewportWidget(QWidget* parent = nullptr);

    //! The surface every editor window asks for: OpenGL 3.3 core with a depth buffer. main() makes
    //! it the default so that all contexts (and Qt's own compositing) agree with the viewport's.
    static QSurfaceFormat surfaceFormat();

    //! The background the viewport clears to; a flat dark grey that keeps bright water readable.
    static QColor clearColor() { return QColor(46, 46, 50); }

    QSize sizeHint() const override { return QSize(960, 640); }

protected:
    void paintGL() override;
};

} // namespace airtrap
