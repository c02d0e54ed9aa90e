#include "viewport/ViewportWidget.h"

#include <QOpenGLContext>
#include <QOpenGLFunctions>

namespace airtrap {

ViewportWidget::ViewportWidget(QWidget* parent) : QOpenGLWidget(parent) {
    // Set per widget as well as by default: tests and embedders may not go through main().
    setFormat(surfaceFormat());
    setMinimumSize(320, 240);
}

QSurfaceFormat ViewportWidget::surfaceFormat() {
    QSurfaceFormat format;
    format.setRenderableType(QSurfaceFormat::OpenGL);
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    format.setStencilBufferSize(8);
    return format;
}

void ViewportWidget::paintGL() {
    QOpenGLFunctions* gl = context()->functions();
    // Set on every frame, not once in initializeGL: the context is shared with Qt's compositor,
    // which may leave its own clear colour behind.
    const QColor background = clearColor();
    gl->glClearColor(background.redF(), background.greenF(), background.blueF(), 1.0f);
    gl->glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
}

} // namespace airtrap
