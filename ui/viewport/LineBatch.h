#pragma once
// A set of line segments drawn in one call, with a width in pixels. Core-profile OpenGL draws
// wide lines inconsistently (often not at all), so a geometry shader turns each segment into a
// screen-aligned quad with a one-pixel anti-aliased fringe. The grid, the axes and the gizmos
// all draw through it.
#include "viewport/Drawable.h"
#include "viewport/LineVertex.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class LineBatch : public Drawable {
public:
    LineBatch();
    ~LineBatch() override;

    //! Replaces the segments: vertices 2i and 2i + 1 are the ends of segment i.
    void setSegments(std::vector<LineVertex> vertices);
    //! Width of every segment in widget pixels.
    void setWidth(float pixels) { width_ = pixels; }
    //! Off: the lines show through everything (a highlighted selection does).
    void setDepthTested(bool tested) { depthTested_ = tested; }

    //! Builds the shader and buffers; the segments are uploaded again on the next draw().
    void initialize() override;
    //! Draws the segments alpha-blended, without writing depth.
    void draw(const RenderContext& context) override;
    //! Frees the GL objects.
    void release() override;

private:
    void upload();

    std::unique_ptr<QOpenGLShaderProgram> program_;
    QOpenGLBuffer buffer_;
    QOpenGLVertexArrayObject vertexArray_;
    std::vector<LineVertex> vertices_;
    int uploadedCount_ = 0;
    bool dirty_ = true;
    float width_ = 1.0f;
    bool depthTested_ = true;
};

} // namespace airtrap
