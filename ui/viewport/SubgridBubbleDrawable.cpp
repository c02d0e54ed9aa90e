#include "viewport/SubgridBubbleDrawable.h"

#include "viewport/BubbleDrawable.h"
#include "viewport/QtVectors.h"
#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"
#include "viewport/SphereSprite.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <cstddef>
#include <cstdint>

namespace airtrap {

namespace {

const char* const kSubgridVertexShaderMain = R"(
layout(location = 0) in vec3 centre;
layout(location = 1) in float radius;
uniform mat4 view;
uniform mat4 projection;
uniform float viewportHeight;
uniform float minimumPixels;
out vec3 eyeCentre;
out float eyeRadius;
void main() {
    vec4 eye = view * vec4(centre, 1.0);
    eyeCentre = eye.xyz;
    eyeRadius = radius;
    gl_Position = projection * eye;
    gl_PointSize =
        max(sphereSpritePixels(radius, projection, viewportHeight, gl_Position.w), minimumPixels);
}
)";

// The trapped bubbles' glassy look on the point's sphere, at the sphere's depth, so points sort
// with the water and the bodies around them.
const char* const kSubgridFragmentShaderMain = R"(
uniform mat4 projection;
uniform vec3 colour;
in vec3 eyeCentre;
in float eyeRadius;
out vec4 fragColour;
void main() {
    vec3 n = sphereSpriteNormal();
    // Seen along the view axis: a point is small enough for the parallel view to hold.
    fragColour = vec4(bubbleShade(n, vec3(0.0, 0.0, 1.0), colour), 1.0);
    gl_FragDepth = sphereSpriteDepth(projection, eyeCentre, n, eyeRadius);
}
)";

QString withVersion(const QString& functions, const char* main) {
    return QStringLiteral("#version 330 core\n") + functions + QString::fromLatin1(main);
}

} // namespace

SubgridBubbleDrawable::SubgridBubbleDrawable() : buffer_(QOpenGLBuffer::VertexBuffer) {
    ownBuffer(buffer_, QOpenGLBuffer::DynamicDraw);
}

SubgridBubbleDrawable::~SubgridBubbleDrawable() = default;

void SubgridBubbleDrawable::setBubbles(const std::vector<SubgridBubble>& bubbles) {
    points_.clear();
    points_.reserve(bubbles.size());
    for (const SubgridBubble& bubble : bubbles) {
        const Vec3f centre = bubble.position.cast<float>();
        points_.push_back({{centre.x(), centre.y(), centre.z()}, float(bubble.radius)});
    }
    markChanged();
}

ShaderSources SubgridBubbleDrawable::shaderSources() const {
    return {"sub-grid bubbles",
            withVersion(SphereSprite::vertexFunctions(), kSubgridVertexShaderMain), QString(),
            withVersion(SphereSprite::fragmentFunctions() + BubbleDrawable::glslShading(),
                        kSubgridFragmentShaderMain)};
}

void SubgridBubbleDrawable::setUpBuffers() {
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    buffer_.bind();
    const auto stride = GLsizei(sizeof(Point));
    gl->glEnableVertexAttribArray(0);
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(
        0, 3, GL_FLOAT, GL_FALSE, stride,
        reinterpret_cast<const void*>(std::intptr_t(offsetof(Point, centre))));
    gl->glVertexAttribPointer(
        1, 1, GL_FLOAT, GL_FALSE, stride,
        reinterpret_cast<const void*>(std::intptr_t(offsetof(Point, radius))));
    buffer_.release();
}

void SubgridBubbleDrawable::upload() {
    static_assert(sizeof(Point) == 4 * sizeof(float), "points go to the GPU as they are");
    buffer_.bind();
    buffer_.allocate(points_.data(), int(points_.size() * sizeof(Point)));
    buffer_.release();
    uploadedCount_ = int(points_.size());
}

void SubgridBubbleDrawable::render(const RenderContext& context, QOpenGLShaderProgram& program) {
    QOpenGLExtraFunctions& gl = context.gl;
    gl.glEnable(GL_DEPTH_TEST);
    gl.glEnable(GL_PROGRAM_POINT_SIZE);
    program.setUniformValue("view", context.view);
    program.setUniformValue("projection", context.projection);
    program.setUniformValue("viewportHeight", float(context.framebufferSize.height()));
    program.setUniformValue("minimumPixels", kMinimumPixels);
    program.setUniformValue("colour", rgbVector(BubbleDrawable::colour()));
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    gl.glDrawArrays(GL_POINTS, 0, uploadedCount_);
    gl.glDisable(GL_PROGRAM_POINT_SIZE);
}

} // namespace airtrap
