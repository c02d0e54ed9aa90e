#pragma once
// The water's free-surface mesh of the shown frame (made by the post stage, paper §4.1) as a
// translucent, lit sheet of sea blue over whatever the view shows beneath it: the particles, the
// bubbles, the bodies. Drawn after the solids without writing depth, so everything behind it
// stays visible through it; smooth vertex normals and a Fresnel-like rim make its curvature
// read. Uploaded again only when the frame's mesh changes.
#include "rigid/TriangleMesh.h"
#include "viewport/Drawable.h"

#include <QColor>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>

namespace airtrap {

class SurfaceDrawable : public Drawable {
public:
    SurfaceDrawable();
    ~SurfaceDrawable() override;

    //! Shows `mesh` (null: none).
    void setMesh(std::shared_ptr<const TriangleMesh> mesh);
    //! Face-on opacity of the translucent look (grazing views are more opaque).
    static constexpr float kTranslucent = 0.55f;

    //! 0 (invisible) to 1 (opaque); kTranslucent by default.
    void setOpacity(float opacity) { opacity_ = opacity; }
    float opacity() const { return opacity_; }
    int triangleCount() const { return mesh_ ? int(mesh_->triangleCount()) : 0; }

    static QColor colour();

    void initialize() override;
    void draw(const RenderContext& context) override;
    void release() override;

private:
    void upload();

    std::unique_ptr<QOpenGLShaderProgram> program_;
    QOpenGLBuffer vertexBuffer_;
    QOpenGLBuffer indexBuffer_;
    QOpenGLVertexArrayObject vertexArray_;
    std::shared_ptr<const TriangleMesh> mesh_;
    int uploadedIndices_ = 0;
    float opacity_ = kTranslucent;
    bool dirty_ = false;
};

} // namespace airtrap
