#include "viewport/BubbleDrawable.h"

#include "viewport/QtVectors.h"
#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"
#include "viewport/SolidMesh.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <cstddef>
#include <cstdint>

namespace airtrap {

namespace {

// Blue well above red, and green hardly above red: no speed colour (whose green runs well ahead
// of red until both reach white) and no body colour has these proportions at any shading.
const QColor kBubbleColour(190, 198, 245);

const char* const kBubbleVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec3 centre;
layout(location = 3) in vec4 rotation; // unit quaternion x y z w
layout(location = 4) in vec3 axes;     // semi-axes, the third along the velocity
uniform mat4 view;
uniform mat4 projection;
out vec3 eyePosition;
out vec3 eyeNormal;
vec3 rotate(vec4 q, vec3 v) {
    return v + 2.0 * cross(q.xyz, cross(q.xyz, v) + q.w * v);
}
void main() {
    vec4 eye = view * vec4(centre + rotate(rotation, axes * position), 1.0);
    eyePosition = eye.xyz;
    // An ellipsoid's normals scale by the inverse axes; the view is rigid.
    eyeNormal = mat3(view) * rotate(rotation, normal / axes);
    gl_Position = projection * eye;
}
)";

// Lit from the upper left of the view like the water; the rim fades towards white and a sharp
// small highlight sits on top, so the sphere reads as a glassy shell rather than a solid ball.
const char* const kBubbleShading = R"(
const vec3 lightDirection = normalize(vec3(-0.35, 0.55, 0.75));
vec3 bubbleShade(vec3 n, vec3 toEye, vec3 colour) {
    float rim = pow(1.0 - max(dot(n, toEye), 0.0), 3.0);
    float diffuse = max(dot(n, lightDirection), 0.0);
    float specular = 0.35 * pow(max(dot(n, normalize(lightDirection + toEye)), 0.0), 128.0);
    vec3 shaded = colour * (0.6 + 0.4 * diffuse);
    return mix(shaded, vec3(1.0), 0.6 * rim) + vec3(specular);
}
)";

const char* const kBubbleFragmentShaderMain = R"(
uniform vec3 colour;
in vec3 eyePosition;
in vec3 eyeNormal;
out vec4 fragColour;
void main() {
    fragColour = vec4(bubbleShade(normalize(eyeNormal), normalize(-eyePosition), colour), 1.0);
}
)";

} // namespace

BubbleDrawable::BubbleDrawable()
    : sphereBuffer_(QOpenGLBuffer::VertexBuffer), instanceBuffer_(QOpenGLBuffer::VertexBuffer) {
    ownBuffer(sphereBuffer_, QOpenGLBuffer::StaticDraw);
    ownBuffer(instanceBuffer_, QOpenGLBuffer::DynamicDraw);
}

BubbleDrawable::~BubbleDrawable() = default;

QColor BubbleDrawable::colour() {
    return kBubbleColour;
}

QString BubbleDrawable::glslShading() {
    return QString::fromLatin1(kBubbleShading);
}

void BubbleDrawable::setShape(const BubbleMeshSettings& settings) {
    shape_ = OscillatingBubbleMesh(settings);
}

void BubbleDrawable::setBubbles(const std::vector<BubbleState>& bubbles) {
    trapped_.clear();
    trapped_.reserve(bubbles.size());
    for (const BubbleState& bubble : bubbles) {
        const Vec3d& centre = bubble.body.position;
        const Quatd turn = OscillatingBubbleMesh::alignment(bubble.body.linearVelocity);
        const Vec3d axes = shape_.semiAxes(bubble.radius, bubble.age);
        trapped_.push_back({{float(centre.x()), float(centre.y()), float(centre.z())},
                            {float(turn.x()), float(turn.y()), float(turn.z()), float(turn.w())},
                            {float(axes.x()), float(axes.y()), float(axes.z())}});
    }
    markChanged();
}

ShaderSources BubbleDrawable::shaderSources() const {
    return {"bubbles", kBubbleVertexShader, QString(),
            QStringLiteral("#version 330 core\n") + glslShading() +
                QString::fromLatin1(kBubbleFragmentShaderMain)};
}

void BubbleDrawable::setUpBuffers() {
    const SolidMesh sphere = SolidMesh::sphere(1.0f);
    sphereVertexCount_ = sphere.vertexCount();
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    sphereBuffer_.bind();
    sphereBuffer_.allocate(sphere.vertices.data(),
                           int(sphere.vertices.size() * sizeof(SolidMesh::Vertex)));
    const auto stride = GLsizei(sizeof(SolidMesh::Vertex));
    gl->glEnableVertexAttribArray(0);
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    gl->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(std::intptr_t(sizeof(QVector3D))));
    sphereBuffer_.release();
    instanceBuffer_.bind();
    const auto instanceStride = GLsizei(sizeof(Instance));
    const int sizes[3] = {3, 4, 3};
    const std::size_t offsets[3] = {offsetof(Instance, centre), offsetof(Instance, rotation),
                                    offsetof(Instance, axes)};
    for (int i = 0; i < 3; ++i) {
        gl->glEnableVertexAttribArray(GLuint(2 + i));
        gl->glVertexAttribPointer(GLuint(2 + i), sizes[i], GL_FLOAT, GL_FALSE, instanceStride,
                                  reinterpret_cast<const void*>(std::intptr_t(offsets[i])));
        gl->glVertexAttribDivisor(GLuint(2 + i), 1); // one per bubble, not per vertex
    }
    instanceBuffer_.release();
}

void BubbleDrawable::upload() {
    static_assert(sizeof(Instance) == 10 * sizeof(float), "instances go to the GPU as they are");
    instanceBuffer_.bind();
    instanceBuffer_.allocate(trapped_.data(), int(trapped_.size() * sizeof(Instance)));
    instanceBuffer_.release();
    uploadedCount_ = int(trapped_.size());
}

void BubbleDrawable::render(const RenderContext& context, QOpenGLShaderProgram& program) {
    context.gl.glEnable(GL_DEPTH_TEST);
    program.setUniformValue("view", context.view);
    program.setUniformValue("projection", context.projection);
    program.setUniformValue("colour", rgbVector(kBubbleColour));
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    context.gl.glDrawArraysInstanced(GL_TRIANGLES, 0, sphereVertexCount_, uploadedCount_);
}

} // namespace airtrap
