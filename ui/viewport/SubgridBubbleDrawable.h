#pragma once
// The sub-grid bubbles of the post stage (paper §4.2) as points: one GL point each, sized to the
// bubble's projected diameter but never under a few pixels, so the smallest stay visible as
// specks, and shaded as a glassy sphere in the trapped bubbles' colour. Thousands of them cost
// one small upload per frame and one draw call.
#include "post/SubgridBubble.h"
#include "viewport/Drawable.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class SubgridBubbleDrawable : public Drawable {
public:
    SubgridBubbleDrawable();
    ~SubgridBubbleDrawable() override;

    //! Shows these bubbles (a frame's post results); empty shows none.
    void setBubbles(const std::vector<SubgridBubble>& bubbles);
    //! Bubbles drawn by the next paint.
    int bubbleCount() const { return int(points_.size()); }

    //! Smallest drawn diameter, in device pixels.
    static constexpr float kMinimumPixels = 3.0f;

    //! Builds the point shader and the buffer.
    void initialize() override;
    //! Uploads changed bubbles, then draws them all depth-tested in one call.
    void draw(const RenderContext& context) override;
    //! Frees the GL objects.
    void release() override;

private:
    void upload();

    //! Per bubble: centre (m) and radius (m), as the buffer holds them.
    struct Point {
        float centre[3];
        float radius;
    };

    std::unique_ptr<QOpenGLShaderProgram> program_;
    QOpenGLBuffer buffer_;
    QOpenGLVertexArrayObject vertexArray_;
    std::vector<Point> points_;
    int uploadedCount_ = 0;
    bool dirty_ = false;
};

} // namespace airtrap
