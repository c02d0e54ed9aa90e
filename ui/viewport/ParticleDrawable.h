#pragma once
// The water of a cached frame as shaded point sprites: each particle is one GL point whose size
// follows the perspective, drawn as a lit sphere and coloured by speed. A frame is uploaded once
// (positions, then speeds, in one buffer) and then drawn with a single call per paint, which keeps
// the view interactive with hundreds of thousands of particles.
#include "cache/FrameFile.h"
#include "viewport/GlDrawable.h"

#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class ParticleDrawable : public GlDrawable {
public:
    ParticleDrawable();
    ~ParticleDrawable() override;

    //! Shows the water of `frame` (null: none). Speeds are computed here, once per frame; the
    //! upload waits for the next draw, so frames that arrive faster than paints are skipped.
    //! The frame is kept: a new context (the widget moved to another window) uploads it again.
    void setFrame(std::shared_ptr<const FrameData> frame);
    //! Radius of the drawn spheres in metres.
    void setRadius(float metres) { radius_ = metres; }
    //! Speed drawn white; 0 and below make it follow each frame's fastest particle.
    void setSpeedScale(float metresPerSecond) { speedScale_ = metresPerSecond; }
    //! The speed drawn white: the fixed scale, or the frame's fastest particle.
    float effectiveSpeedScale() const;
    //! Speed of the current frame's fastest particle, m/s.
    float maxSpeed() const { return maxSpeed_; }
    //! Particles of the current frame.
    int particleCount() const { return count_; }
    //! While the camera moves, frames with more particles than `budget` draw every k-th one
    //! (k = count / budget, rounded up) with spheres k^(1/3) times larger, so the water keeps
    //! its look and the view keeps up with the mouse on slow (software) OpenGL. 0 disables it.
    void setMovingBudget(int budget) { movingBudget_ = budget; }
    //! Whether the camera is moving (the reduced drawing applies).
    void setMoving(bool moving) { moving_ = moving; }
    //! Every how many particles one is drawn in the next paint (1 = all).
    int drawStride() const;

private:
    ShaderSources shaderSources() const override;
    //! The frame's positions, then its speeds, in one buffer.
    void upload() override;
    bool hasUploaded() const override { return uploadedCount_ > 0; }
    //! All particles (or every drawStride()-th) in one call.
    void render(const RenderContext& context, QOpenGLShaderProgram& program) override;
    void releaseUploads() override { uploadedCount_ = 0; }
    //! Points the vertex attributes at every `stride`-th particle of the buffer.
    void bindAttributes(int stride);

    QOpenGLBuffer buffer_;
    std::shared_ptr<const FrameData> frame_;
    std::vector<float> speeds_; //!< of frame_, in its particle order
    int count_ = 0;
    int uploadedCount_ = 0;
    float radius_ = 0.01f;
    float speedScale_ = 0.0f;
    float maxSpeed_ = 0.0f;
    int movingBudget_ = 0;
    bool moving_ = false;
    int boundStride_ = 1;
};

} // namespace airtrap
