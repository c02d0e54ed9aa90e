#pragma once
// The trapped air bubbles of a cached frame in a pale ice blue, apart from the water's speed
// colours and from the bodies' motion colours, shaped as they are exported: the oscillating
// ellipsoid of paper eqs. 7–10 (OscillatingBubbleMesh), stretched along the bubble's velocity and
// wobbling after its birth. Every bubble is one instance of a unit sphere, turned and scaled by
// its ellipsoid's axes, so a frame with thousands of bubbles is still one draw call; the sphere
// is uploaded once, the instances again whenever the frame changes.
#include "bubbles/BubbleState.h"
#include "post/OscillatingBubbleMesh.h"
#include "viewport/GlDrawable.h"

#include <QColor>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <QString>
#include <QVector4D>
#include <memory>
#include <vector>

namespace airtrap {

class BubbleDrawable : public GlDrawable {
public:
    BubbleDrawable();
    ~BubbleDrawable() override;

    //! How the bubbles wobble (the scene's bubble_mesh section); applies from the next
    //! setBubbles().
    void setShape(const BubbleMeshSettings& settings);
    //! Shows these bubbles (a frame's SimulationState::bubbles); empty shows none.
    void setBubbles(const std::vector<BubbleState>& bubbles);
    //! Trapped bubbles drawn by the next paint.
    int bubbleCount() const { return int(trapped_.size()); }

    //! The bubbles' colour before shading (the sub-grid bubbles' too).
    static QColor colour();
    //! GLSL source of `vec3 bubbleShade(vec3 normal, vec3 toEye, vec3 colour)`, the bubbles'
    //! glassy look, for every shader that draws bubbles.
    static QString glslShading();

private:
    ShaderSources shaderSources() const override;
    //! The unit sphere, once, and the instance attributes' layout.
    void setUpBuffers() override;
    //! The bubbles as instances.
    void upload() override;
    bool hasUploaded() const override { return uploadedCount_ > 0; }
    //! All bubbles depth-tested in one instanced call.
    void render(const RenderContext& context, QOpenGLShaderProgram& program) override;
    void releaseUploads() override { uploadedCount_ = 0; }

    QOpenGLBuffer sphereBuffer_;
    QOpenGLBuffer instanceBuffer_;
    int sphereVertexCount_ = 0;
    //! Per bubble: centre (m), rotation (x y z w, unit sphere's z onto the velocity), semi-axes
    //! (m).
    struct Instance {
        float centre[3];
        float rotation[4];
        float axes[3];
    };

    OscillatingBubbleMesh shape_{BubbleMeshSettings{}};
    std::vector<Instance> trapped_;
    int uploadedCount_ = 0;
};

} // namespace airtrap
