#include "viewport/SurfaceDrawable.h"

#include "rigid/TriangleMesh.h"
#include "viewport/QtVectors.h"
#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QVector3D>
#include <algorithm>
#include <cstdint>
#include <vector>

namespace airtrap {

namespace {

const QColor kSurfaceColour(40, 120, 190);

const char* const kSurfaceVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
uniform mat4 view;
uniform mat4 projection;
out vec3 eyePosition;
out vec3 eyeNormal;
void main() {
    vec4 eye = view * vec4(position, 1.0);
    eyePosition = eye.xyz;
    eyeNormal = mat3(view) * normal; // the view is rigid
    gl_Position = projection * eye;
}
)";

// Grazing views are more opaque and paler than straight-on ones, as on real water, which is what
// shows the surface's shape; a small highlight marks its slopes.
const char* const kSurfaceFragmentShader = R"(#version 330 core
uniform vec3 colour;
uniform float opacity;
in vec3 eyePosition;
in vec3 eyeNormal;
out vec4 fragColour;
const vec3 lightDirection = normalize(vec3(-0.35, 0.55, 0.75));
void main() {
    vec3 n = normalize(eyeNormal);
    vec3 toEye = normalize(-eyePosition);
    if (dot(n, toEye) < 0.0) {
        n = -n; // seen from below the surface
    }
    float facing = max(dot(n, toEye), 0.0);
    float rim = pow(1.0 - facing, 3.0);
    float diffuse = max(dot(n, lightDirection), 0.0);
    float specular = 0.5 * pow(max(dot(n, normalize(lightDirection + toEye)), 0.0), 64.0);
    vec3 shaded = mix(colour * (0.55 + 0.45 * diffuse), vec3(0.85, 0.92, 1.0), 0.5 * rim);
    fragColour = vec4(shaded + vec3(specular), mix(opacity, 1.0, 0.6 * rim));
}
)";

//! Each edge of `mesh` once, as index pairs: neighbouring triangles share theirs, and a line
//! drawn twice with blending would be darker than its neighbours.
std::vector<GLuint> distinctEdges(const TriangleMesh& mesh) {
    std::vector<std::uint64_t> keys = mesh.sortedEdgeKeys();
    keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
    std::vector<GLuint> indices;
    indices.reserve(2 * keys.size());
    for (std::uint64_t key : keys) {
        indices.push_back(GLuint(key >> 32));
        indices.push_back(GLuint(key & 0xFFFFFFFFu));
    }
    return indices;
}

} // namespace

SurfaceDrawable::SurfaceDrawable()
    : vertexBuffer_(QOpenGLBuffer::VertexBuffer), indexBuffer_(QOpenGLBuffer::IndexBuffer),
      edgeIndexBuffer_(QOpenGLBuffer::IndexBuffer) {
    ownBuffer(vertexBuffer_, QOpenGLBuffer::DynamicDraw);
    ownBuffer(indexBuffer_, QOpenGLBuffer::DynamicDraw);
    ownBuffer(edgeIndexBuffer_, QOpenGLBuffer::DynamicDraw);
}

SurfaceDrawable::~SurfaceDrawable() = default;

QColor SurfaceDrawable::colour() {
    return kSurfaceColour;
}

void SurfaceDrawable::setMesh(std::shared_ptr<const TriangleMesh> mesh) {
    mesh_ = std::move(mesh);
    markChanged();
}

ShaderSources SurfaceDrawable::shaderSources() const {
    return {"surface", kSurfaceVertexShader, QString(), kSurfaceFragmentShader};
}

void SurfaceDrawable::setUpBuffers() {
    edgeArray_.create();
    bindVertices(vertexArray(), indexBuffer_);
    bindVertices(edgeArray_, edgeIndexBuffer_);
}

void SurfaceDrawable::bindVertices(QOpenGLVertexArrayObject& array, QOpenGLBuffer& indices) {
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    QOpenGLVertexArrayObject::Binder binder(&array);
    vertexBuffer_.bind();
    indices.bind(); // the element buffer binding is part of the vertex array's state
    const auto stride = GLsizei(6 * sizeof(float));
    gl->glEnableVertexAttribArray(0);
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, stride, nullptr);
    gl->glVertexAttribPointer(1, 3, GL_FLOAT, GL_FALSE, stride,
                              reinterpret_cast<const void*>(std::intptr_t(3 * sizeof(float))));
    vertexBuffer_.release();
}

void SurfaceDrawable::upload() {
    edgesDirty_ = true;
    uploadedIndices_ = 0;
    if (!mesh_ || mesh_->triangles.empty())
        return;
    const std::vector<Vec3d> normals = mesh_->vertexNormals();
    std::vector<float> vertices;
    vertices.reserve(6 * mesh_->vertices.size());
    for (std::size_t v = 0; v < mesh_->vertices.size(); ++v)
        for (const Vec3d* value : {&mesh_->vertices[v], &normals[v]})
            for (int axis = 0; axis < 3; ++axis)
                vertices.push_back(float((*value)[axis]));
    QOpenGLVertexArrayObject::Binder binder(&vertexArray());
    vertexBuffer_.bind();
    vertexBuffer_.allocate(vertices.data(), int(vertices.size() * sizeof(float)));
    vertexBuffer_.release();
    // Triangles are three uint32 indices each, laid out as the element buffer wants them.
    static_assert(sizeof(TriangleMesh::Triangle) == 3 * sizeof(GLuint));
    indexBuffer_.bind();
    indexBuffer_.allocate(mesh_->triangles.data(),
                          int(mesh_->triangles.size() * sizeof(TriangleMesh::Triangle)));
    uploadedIndices_ = int(3 * mesh_->triangles.size());
}

void SurfaceDrawable::uploadEdges() {
    edgesDirty_ = false;
    uploadedEdgeIndices_ = 0;
    if (!mesh_ || mesh_->triangles.empty())
        return;
    const std::vector<GLuint> edges = distinctEdges(*mesh_);
    QOpenGLVertexArrayObject::Binder binder(&edgeArray_);
    edgeIndexBuffer_.bind();
    edgeIndexBuffer_.allocate(edges.data(), int(edges.size() * sizeof(GLuint)));
    uploadedEdgeIndices_ = int(edges.size());
}

void SurfaceDrawable::render(const RenderContext& context, QOpenGLShaderProgram& program) {
    const bool wireframe = shading_ == SurfaceShading::Wireframe;
    if (wireframe && edgesDirty_)
        uploadEdges();
    QOpenGLExtraFunctions& gl = context.gl;
    gl.glEnable(GL_DEPTH_TEST);
    gl.glEnable(GL_BLEND);
    gl.glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
    gl.glDepthMask(GL_FALSE); // what lies behind the sheet stays visible through it
    program.setUniformValue("view", context.view);
    program.setUniformValue("projection", context.projection);
    // Lines are thin: paler than the sheet so that they read against the dark background.
    program.setUniformValue("colour",
                            rgbVector(wireframe ? kSurfaceColour.lighter(160) : kSurfaceColour));
    program.setUniformValue("opacity", opacity());
    if (wireframe) {
        QOpenGLVertexArrayObject::Binder binder(&edgeArray_);
        gl.glDrawElements(GL_LINES, uploadedEdgeIndices_, GL_UNSIGNED_INT, nullptr);
    } else {
        QOpenGLVertexArrayObject::Binder binder(&vertexArray());
        gl.glDrawElements(GL_TRIANGLES, uploadedIndices_, GL_UNSIGNED_INT, nullptr);
    }
    gl.glDepthMask(GL_TRUE);
    gl.glDisable(GL_BLEND);
}

void SurfaceDrawable::releaseUploads() {
    edgeArray_.destroy();
    uploadedIndices_ = 0;
    uploadedEdgeIndices_ = 0;
}

} // namespace airtrap
