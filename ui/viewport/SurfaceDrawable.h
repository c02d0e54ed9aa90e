#pragma once
// The water's free-surface mesh of the shown frame (made by the post stage, paper §4.1) as a
// translucent, lit sheet of sea blue over whatever the view shows beneath it: the particles, the
// bubbles, the bodies. Drawn after the solids without writing depth, so everything behind it
// stays visible through it; smooth vertex normals and a Fresnel-like rim make its curvature
// read. Opaque, it hides what it covers; as a wireframe, its triangles' edges are drawn once each
// (a shared edge is one line), lit like the sheet. Uploaded again only when the mesh changes.
#include "rigid/TriangleMesh.h"
#include "viewport/GlDrawable.h"
#include "viewport/SurfaceShading.h"

#include <QColor>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>

namespace airtrap {

class SurfaceDrawable : public GlDrawable {
public:
    SurfaceDrawable();
    ~SurfaceDrawable() override;

    //! Shows `mesh` (null: none).
    void setMesh(std::shared_ptr<const TriangleMesh> mesh);
    //! Face-on opacity of the translucent look (grazing views are more opaque).
    static constexpr float kTranslucent = 0.55f;

    //! Translucent (the default), opaque or wireframe.
    void setShading(SurfaceShading shading) { shading_ = shading; }
    SurfaceShading shading() const { return shading_; }
    //! Face-on opacity: kTranslucent when translucent, 1 otherwise.
    float opacity() const { return shading_ == SurfaceShading::Translucent ? kTranslucent : 1.0f; }
    int triangleCount() const { return mesh_ ? int(mesh_->triangleCount()) : 0; }
    //! Distinct edges of the mesh the wireframe last drew.
    int edgeCount() const { return uploadedEdgeIndices_ / 2; }

    static QColor colour();

private:
    ShaderSources shaderSources() const override;
    //! The edges' vertex array, and both arrays' attribute layout.
    void setUpBuffers() override;
    //! The vertices with their normals and the triangles; the edges wait for the wireframe.
    void upload() override;
    bool hasUploaded() const override { return uploadedIndices_ > 0; }
    //! The sheet blended over what lies behind it, or its edges.
    void render(const RenderContext& context, QOpenGLShaderProgram& program) override;
    void releaseUploads() override;

    //! Attaches the vertex buffer's position and normal to `array`, with `indices` as its elements.
    void bindVertices(QOpenGLVertexArrayObject& array, QOpenGLBuffer& indices);
    void uploadEdges();

    QOpenGLBuffer vertexBuffer_;
    QOpenGLBuffer indexBuffer_;
    // The wireframe: the same vertices, a second vertex array for the edge index buffer.
    QOpenGLBuffer edgeIndexBuffer_;
    QOpenGLVertexArrayObject edgeArray_;
    std::shared_ptr<const TriangleMesh> mesh_;
    int uploadedIndices_ = 0;
    int uploadedEdgeIndices_ = 0;
    SurfaceShading shading_ = SurfaceShading::Translucent;
    bool edgesDirty_ = false; // the edges are found only when the wireframe is first drawn
};

} // namespace airtrap
