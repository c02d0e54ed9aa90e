#pragma once
// The sub-grid bubbles of the post stage (paper §4.2) as points: one GL point each, sized to the
// bubble's projected diameter but never under a few pixels, so the smallest stay visible as
// specks, and shaded as a glassy sphere in the trapped bubbles' colour. Thousands of them cost
// one small upload per frame and one draw call.
#include "post/SubgridBubble.h"
#include "viewport/GlDrawable.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class SubgridBubbleDrawable : public GlDrawable {
public:
    SubgridBubbleDrawable();
    ~SubgridBubbleDrawable() override;

    //! Shows these bubbles (a frame's post results); empty shows none.
    void setBubbles(const std::vector<SubgridBubble>& bubbles);
    //! Bubbles drawn by the next paint.
    int bubbleCount() const { return int(points_.size()); }

    //! Smallest drawn diameter, in device pixels.
    static constexpr float kMinimumPixels = 3.0f;

private:
    ShaderSources shaderSources() const override;
    void setUpBuffers() override;
    void upload() override;
    bool hasUploaded() const override { return uploadedCount_ > 0; }
    //! All bubbles depth-tested in one call.
    void render(const RenderContext& context, QOpenGLShaderProgram& program) override;
    void releaseUploads() override { uploadedCount_ = 0; }

    //! Per bubble: centre (m) and radius (m), as the buffer holds them.
    struct Point {
        float centre[3];
        float radius;
    };

    QOpenGLBuffer buffer_;
    std::vector<Point> points_;
    int uploadedCount_ = 0;
};

} // namespace airtrap
