#pragma once
// The trapped air bubbles of a cached frame as lit spheres in a pale ice blue, apart from the
// water's speed colours and from the bodies' motion colours. Every bubble is one instance of a
// unit sphere scaled by its radius, so a frame with thousands of bubbles is still one draw call;
// the sphere is uploaded once, the centres and radii again whenever the frame changes.
#include "bubbles/BubbleState.h"
#include "viewport/Drawable.h"

#include <QColor>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QVector4D>
#include <memory>
#include <vector>

namespace airtrap {

class BubbleDrawable : public Drawable {
public:
    BubbleDrawable();
    ~BubbleDrawable() override;

    //! Shows these bubbles (a frame's SimulationState::bubbles); empty shows none.
    void setBubbles(const std::vector<BubbleState>& bubbles);
    //! Bubbles drawn by the next paint.
    int bubbleCount() const { return int(instances_.size()); }

    //! The bubbles' colour before shading.
    static QColor colour();

    //! Builds the shader, the sphere and the instance buffer.
    void initialize() override;
    //! Uploads changed bubbles, then draws them all depth-tested in one call.
    void draw(const RenderContext& context) override;
    //! Frees the GL objects.
    void release() override;

private:
    void uploadSphere();
    void uploadInstances();

    std::unique_ptr<QOpenGLShaderProgram> program_;
    QOpenGLBuffer sphereBuffer_;
    QOpenGLBuffer instanceBuffer_;
    QOpenGLVertexArrayObject vertexArray_;
    int sphereVertexCount_ = 0;
    std::vector<QVector4D> instances_; //!< centre (m) and radius (m) of each bubble
    int uploadedCount_ = 0;
    bool dirty_ = false;
};

} // namespace airtrap
