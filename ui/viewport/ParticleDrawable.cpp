#include "viewport/ParticleDrawable.h"

#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"
#include "viewport/SpeedColormap.h"
#include "viewport/SphereSprite.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <algorithm>
#include <cmath>
#include <cstdint>

namespace airtrap {

// Positions go to the GPU straight from the frame's array.
static_assert(sizeof(Vec3f) == 3 * sizeof(float));

namespace {

// Slowest scale the colours stretch over: water at rest (frame 1) must stay blue, not divide by 0.
constexpr float kMinSpeedScale = 0.05f; // m/s

// The sprite covers the sphere's projected diameter.
const char* const kParticleVertexShaderMain = R"(
layout(location = 0) in vec3 position;
layout(location = 1) in float speed;
uniform mat4 view;
uniform mat4 projection;
uniform float radius;
uniform float viewportHeight;
uniform float speedScale;
out vec3 eyeCentre;
out float colourParameter;
void main() {
    vec4 eye = view * vec4(position, 1.0);
    eyeCentre = eye.xyz;
    gl_Position = projection * eye;
    gl_PointSize = max(sphereSpritePixels(radius, projection, viewportHeight, gl_Position.w), 1.0);
    colourParameter = speed / speedScale;
}
)";

// Shades the sprite as a sphere: the normal follows from the position on the disc; a key light
// from the upper left of the view plus ambient, a little specular; depth is that of the sphere's
// surface so that neighbouring particles intersect like balls, not like flat discs.
const char* const kFragmentShaderMain = R"(
uniform mat4 projection;
uniform float radius;
in vec3 eyeCentre;
in float colourParameter;
out vec4 fragColour;
const vec3 lightDirection = normalize(vec3(-0.35, 0.55, 0.75));
void main() {
    vec3 normal = sphereSpriteNormal();
    float diffuse = max(dot(normal, lightDirection), 0.0);
    vec3 halfway = normalize(lightDirection + vec3(0.0, 0.0, 1.0));
    float specular = 0.3 * pow(max(dot(normal, halfway), 0.0), 48.0);
    vec3 base = speedColour(colourParameter);
    fragColour = vec4(base * (0.35 + 0.65 * diffuse) + vec3(specular), 1.0);
    gl_FragDepth = sphereSpriteDepth(projection, eyeCentre, normal, radius);
}
)";

QString vertexShader() {
    return QStringLiteral("#version 330 core\n") + SphereSprite::vertexFunctions() +
           QString::fromLatin1(kParticleVertexShaderMain);
}

QString fragmentShader() {
    return QStringLiteral("#version 330 core\n") + SpeedColormap::glslFunction() +
           SphereSprite::fragmentFunctions() + QString::fromLatin1(kFragmentShaderMain);
}

} // namespace

ParticleDrawable::ParticleDrawable() : buffer_(QOpenGLBuffer::VertexBuffer) {
    ownBuffer(buffer_, QOpenGLBuffer::DynamicDraw);
}

ParticleDrawable::~ParticleDrawable() = default;

void ParticleDrawable::setFrame(std::shared_ptr<const FrameData> frame) {
    const std::vector<Vec3f> empty;
    const std::vector<Vec3f>& velocities = frame ? frame->state.fluid.velocities : empty;
    speeds_.resize(velocities.size());
    std::transform(velocities.begin(), velocities.end(), speeds_.begin(),
                   [](const Vec3f& v) { return v.norm(); });
    maxSpeed_ = speeds_.empty() ? 0.0f : *std::max_element(speeds_.begin(), speeds_.end());
    count_ = int(speeds_.size());
    frame_ = std::move(frame);
    markChanged();
}

float ParticleDrawable::effectiveSpeedScale() const {
    return std::max(speedScale_ > 0.0f ? speedScale_ : maxSpeed_, kMinSpeedScale);
}

ShaderSources ParticleDrawable::shaderSources() const {
    return {"particles", vertexShader(), QString(), fragmentShader()};
}

void ParticleDrawable::upload() {
    uploadedCount_ = 0;
    if (!frame_)
        return;
    const std::vector<Vec3f>& positions = frame_->state.fluid.positions;
    const int positionBytes = int(positions.size() * sizeof(Vec3f));
    const int speedBytes = int(speeds_.size() * sizeof(float));
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    buffer_.bind();
    buffer_.allocate(positionBytes + speedBytes);
    buffer_.write(0, positions.data(), positionBytes);
    buffer_.write(positionBytes, speeds_.data(), speedBytes);
    gl->glEnableVertexAttribArray(0);
    gl->glEnableVertexAttribArray(1);
    buffer_.release();
    uploadedCount_ = int(positions.size());
    boundStride_ = 0; // attributes point into the old buffer layout until bound again
}

void ParticleDrawable::bindAttributes(int stride) {
    // The particles are stored cell by cell, so every k-th one samples the whole volume evenly;
    // a prefix of the buffer would show only part of the water.
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    const std::intptr_t speedsOffset = std::intptr_t(uploadedCount_) * std::intptr_t(sizeof(Vec3f));
    buffer_.bind();
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, GLsizei(stride * sizeof(Vec3f)), nullptr);
    gl->glVertexAttribPointer(1, 1, GL_FLOAT, GL_FALSE, GLsizei(stride * sizeof(float)),
                              reinterpret_cast<const void*>(speedsOffset));
    buffer_.release();
    boundStride_ = stride;
}

int ParticleDrawable::drawStride() const {
    if (!moving_ || movingBudget_ <= 0 || uploadedCount_ <= movingBudget_)
        return 1;
    return (uploadedCount_ + movingBudget_ - 1) / movingBudget_;
}

void ParticleDrawable::render(const RenderContext& context, QOpenGLShaderProgram& program) {
    QOpenGLExtraFunctions& gl = context.gl;
    gl.glEnable(GL_DEPTH_TEST);
    gl.glEnable(GL_PROGRAM_POINT_SIZE);
    program.setUniformValue("view", context.view);
    program.setUniformValue("projection", context.projection);
    const int stride = drawStride();
    // Fewer, larger spheres fill about the same volume: the radius grows with the cube root.
    program.setUniformValue("radius", radius_ * std::cbrt(float(stride)));
    program.setUniformValue("viewportHeight", float(context.framebufferSize.height()));
    program.setUniformValue("speedScale", effectiveSpeedScale());
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    if (stride != boundStride_)
        bindAttributes(stride);
    gl.glDrawArrays(GL_POINTS, 0, (uploadedCount_ + stride - 1) / stride);
    gl.glDisable(GL_PROGRAM_POINT_SIZE);
}

} // namespace airtrap
