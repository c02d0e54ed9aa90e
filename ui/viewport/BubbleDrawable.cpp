#include "viewport/BubbleDrawable.h"

#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"
#include "viewport/SolidMesh.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <cstdint>

namespace airtrap {

// Instances go to the GPU as they are: centre and radius, four floats.
static_assert(sizeof(QVector4D) == 4 * sizeof(float));

namespace {

// Blue well above red, and green hardly above red: no speed colour (whose green runs well ahead
// of red until both reach white) and no body colour has these proportions at any shading.
const QColor kBubbleColour(190, 198, 245);

const char* const kVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec4 bubble; // centre, radius
uniform mat4 view;
uniform mat4 projection;
out vec3 eyePosition;
out vec3 eyeNormal;
void main() {
    vec4 eye = view * vec4(bubble.xyz + bubble.w * position, 1.0);
    eyePosition = eye.xyz;
    eyeNormal = mat3(view) * normal; // the view is rigid: no inverse transpose needed
    gl_Position = projection * eye;
}
)";

// Lit from the upper left of the view like the water; the rim fades towards white and a sharp
// small highlight sits on top, so the sphere reads as a glassy shell rather than a solid ball.
const char* const kFragmentShader = R"(#version 330 core
uniform vec3 colour;
in vec3 eyePosition;
in vec3 eyeNormal;
out vec4 fragColour;
const vec3 lightDirection = normalize(vec3(-0.35, 0.55, 0.75));
void main() {
    vec3 n = normalize(eyeNormal);
    vec3 toEye = normalize(-eyePosition);
    float rim = pow(1.0 - max(dot(n, toEye), 0.0), 3.0);
    float diffuse = max(dot(n, lightDirection), 0.0);
    float specular = 0.35 * pow(max(dot(n, normalize(lightDirection + toEye)), 0.0), 128.0);
    vec3 shaded = colour * (0.6 + 0.4 * diffuse);
    fragColour = vec4(mix(shaded, vec3(1.0), 0.6 * rim) + vec3(specular), 1.0);
}
)";

QVector3D rgb(const QColor& colour) {
    return QVector3D(float(colour.redF()), float(colour.greenF()), float(colour.blueF()));
}

} // namespace

BubbleDrawable::BubbleDrawable()
    : sphereBuffer_(QOpenGLBuffer::VertexBuffer), instanceBuffer_(QOpenGLBuffer::VertexBuffer) {}

BubbleDrawable::~BubbleDrawable() = default;

QColor BubbleDrawable::colour() {
    return kBubbleColour;
}

void BubbleDrawable::setBubbles(const std::vector<BubbleState>& bubbles) {
    instances_.clear();
    instances_.reserve(bubbles.size());
    for (const BubbleState& bubble : bubbles) {
        const Vec3d& centre = bubble.body.position;
        instances_.emplace_back(float(centre.x()), float(centre.y()), float(centre.z()),
                                float(bubble.radius));
    }
    dirty_ = true;
}

void BubbleDrawable::initialize() {
    program_ = ShaderSources{"bubbles", kVertexShader, QString(), kFragmentShader}.build();
    vertexArray_.create();
    sphereBuffer_.create();
    sphereBuffer_.setUsagePattern(QOpenGLBuffer::StaticDraw);
    instanceBuffer_.create();
    instanceBuffer_.setUsagePattern(QOpenGLBuffer::DynamicDraw);
    uploadSphere();
    uploadedCount_ = 0;
    dirty_ = true;
}

void BubbleDrawable::uploadSphere() {
    const SolidMesh sphere = SolidMesh::sphere(1.0f);
    sphereVertexCount_ = sphere.vertexCount();
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    QOpenGLVertexArrayObject::Binder binder(&vertexArray_);
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
    gl->glEnableVertexAttribArray(2);
    gl->glVertexAttribPointer(2, 4, GL_FLOAT, GL_FALSE, GLsizei(sizeof(QVector4D)), nullptr);
    gl->glVertexAttribDivisor(2, 1); // one centre and radius per sphere, not per vertex
    instanceBuffer_.release();
}

void BubbleDrawable::uploadInstances() {
    dirty_ = false;
    instanceBuffer_.bind();
    instanceBuffer_.allocate(instances_.data(), int(instances_.size() * sizeof(QVector4D)));
    instanceBuffer_.release();
    uploadedCount_ = int(instances_.size());
}

void BubbleDrawable::draw(const RenderContext& context) {
    if (!program_)
        return;
    if (dirty_)
        uploadInstances();
    if (uploadedCount_ == 0)
        return;
    context.gl.glEnable(GL_DEPTH_TEST);
    program_->bind();
    program_->setUniformValue("view", context.view);
    program_->setUniformValue("projection", context.projection);
    program_->setUniformValue("colour", rgb(kBubbleColour));
    QOpenGLVertexArrayObject::Binder binder(&vertexArray_);
    context.gl.glDrawArraysInstanced(GL_TRIANGLES, 0, sphereVertexCount_, uploadedCount_);
    program_->release();
}

void BubbleDrawable::release() {
    program_.reset();
    sphereBuffer_.destroy();
    instanceBuffer_.destroy();
    vertexArray_.destroy();
    uploadedCount_ = 0;
}

} // namespace airtrap
