#include "viewport/BodyDrawable.h"

#include "viewport/BoxGizmoDrawable.h"
#include "viewport/QtVectors.h"
#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QVector3D>
#include <cstdint>

namespace airtrap {

// Positions and normals go to the GPU as they are: three floats each, interleaved.
static_assert(sizeof(SolidMesh::Vertex) == 6 * sizeof(float));

namespace {

const QColor kStaticColour(150, 150, 155);
const QColor kDynamicColour(215, 85, 55);
const QColor kKinematicColour(70, 115, 225);

const char* const kBodyVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 model;
uniform mat4 viewProjection;
out vec3 worldNormal;
void main() {
    worldNormal = mat3(model) * normal; // the pose is rigid: no inverse transpose needed
    gl_Position = viewProjection * model * vec4(position, 1.0);
}
)";

// A key light from above and the front plus generous ambient, so the motion's colour reads on
// every side; lit from both sides, so an inside-out mesh still looks solid.
const char* const kBodyFragmentShader = R"(#version 330 core
uniform vec3 colour;
in vec3 worldNormal;
out vec4 fragColour;
const vec3 lightDirection = normalize(vec3(-0.3, 0.8, 0.5));
void main() {
    vec3 n = normalize(worldNormal);
    if (!gl_FrontFacing) {
        n = -n;
    }
    float diffuse = abs(dot(n, lightDirection));
    fragColour = vec4(colour * (0.5 + 0.5 * diffuse), 1.0);
}
)";

} // namespace

BodyDrawable::BodyDrawable() : buffer_(QOpenGLBuffer::VertexBuffer) {
    ownBuffer(buffer_, QOpenGLBuffer::StaticDraw);
}

BodyDrawable::~BodyDrawable() = default;

QColor BodyDrawable::colourOf(const std::string& motion) {
    if (motion == "static")
        return kStaticColour;
    if (motion == "kinematic")
        return kKinematicColour;
    return kDynamicColour;
}

void BodyDrawable::setBodies(const SceneBodies& bodies) {
    bodies_ = bodies;
    std::vector<std::shared_ptr<const SolidMesh>> solids;
    for (const SceneBodies::Body& body : bodies_.bodies())
        solids.push_back(body.solid);
    if (solids != uploaded_)
        markChanged();
}

ShaderSources BodyDrawable::shaderSources() const {
    return {"bodies", kBodyVertexShader, QString(), kBodyFragmentShader};
}

void BodyDrawable::upload() {
    uploaded_.clear();
    firstVertex_.clear();
    std::vector<SolidMesh::Vertex> vertices;
    for (const SceneBodies::Body& body : bodies_.bodies()) {
        uploaded_.push_back(body.solid);
        firstVertex_.push_back(int(vertices.size()));
        if (body.solid)
            vertices.insert(vertices.end(), body.solid->vertices.begin(),
                            body.solid->vertices.end());
    }
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    buffer_.bind();
    buffer_.allocate(vertices.data(), int(vertices.size() * sizeof(SolidMesh::Vertex)));
    const auto stride = GLsizei(sizeof(SolidMesh::Vertex));
    gl->glEnableVertexAttribArray(0);
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    gl->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(std::intptr_t(sizeof(QVector3D))));
    buffer_.release();
}

void BodyDrawable::render(const RenderContext& context, QOpenGLShaderProgram& program) {
    context.gl.glEnable(GL_DEPTH_TEST);
    program.setUniformValue("viewProjection", context.viewProjection);
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    const std::vector<SceneBodies::Body>& bodies = bodies_.bodies();
    for (std::size_t i = 0; i < bodies.size() && i < uploaded_.size(); ++i) {
        const SceneBodies::Body& body = bodies[i];
        if (!body.solid)
            continue;
        const QColor colour =
            body.item == selection_ ? BoxGizmoDrawable::highlightColour() : colourOf(body.motion);
        program.setUniformValue("model", body.pose);
        program.setUniformValue("colour", rgbVector(colour));
        context.gl.glDrawArrays(GL_TRIANGLES, firstVertex_[i], body.solid->vertexCount());
    }
}

void BodyDrawable::releaseUploads() {
    uploaded_.clear();
    firstVertex_.clear();
}

} // namespace airtrap
