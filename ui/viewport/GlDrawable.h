#pragma once
// The life cycle every drawable with its own shader shares (Drawable's contract): initialize()
// builds the program, creates the vertex array and the buffers the drawable registered, and lets
// it lay them out; draw() does nothing before that or when the shader failed, uploads what
// changed since the last draw, draws only when something is uploaded, with the program bound;
// release() frees them all. A drawable supplies its shaders, its upload and its draw calls.
#include "viewport/Drawable.h"
#include "viewport/ShaderSources.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class GlDrawable : public Drawable {
public:
    void initialize() final;
    void draw(const RenderContext& context) final;
    void release() final;

protected:
    //! `buffer` is created with `usage` in initialize() and destroyed in release(); it must
    //! outlive this object's GL life (a member of the drawable).
    void ownBuffer(QOpenGLBuffer& buffer, QOpenGLBuffer::UsagePattern usage);
    //! The data changed: the next draw uploads it.
    void markChanged() { changed_ = true; }
    //! The drawable's vertex array, created by initialize().
    QOpenGLVertexArrayObject& vertexArray() { return vertexArray_; }

    virtual ShaderSources shaderSources() const = 0;
    //! After the vertex array and buffers exist: attribute layouts, data that never changes.
    virtual void setUpBuffers() {}
    //! Uploads the data after a change (always once after initialize()).
    virtual void upload() = 0;
    //! Whether the upload left anything to draw.
    virtual bool hasUploaded() const = 0;
    //! Draws the uploaded data; `program` is bound.
    virtual void render(const RenderContext& context, QOpenGLShaderProgram& program) = 0;
    //! Forgets what was uploaded and frees GL objects of its own, its context still current.
    virtual void releaseUploads() {}

private:
    struct OwnedBuffer {
        QOpenGLBuffer* buffer;
        QOpenGLBuffer::UsagePattern usage;
    };

    std::unique_ptr<QOpenGLShaderProgram> program_;
    QOpenGLVertexArrayObject vertexArray_;
    std::vector<OwnedBuffer> buffers_;
    bool changed_ = true;
};

} // namespace airtrap
