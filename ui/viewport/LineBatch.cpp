#include "viewport/LineBatch.h"

#include "viewport/RenderContext.h"
#include "viewport/ShaderSources.h"

#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QVector2D>

namespace airtrap {

namespace {

const char* const kLineBatchVertexShader = R"(#version 330 core
layout(location = 0) in vec3 position;
layout(location = 1) in vec4 colour;
uniform mat4 viewProjection;
out vec4 vertexColour;
void main() {
    gl_Position = viewProjection * vec4(position, 1.0);
    vertexColour = colour;
}
)";

// Expands each segment into a quad `halfWidth` + 1 pixels to either side (the extra pixel is the
// anti-aliased fringe) and as much past each end, so that box corners meet without notches.
const char* const kGeometryShader = R"(#version 330 core
layout(lines) in;
layout(triangle_strip, max_vertices = 4) out;
uniform vec2 viewportSize;
uniform float halfWidth;
in vec4 vertexColour[];
out vec4 lineColour;
noperspective out float across;

void emitCorner(vec4 clip, vec2 offsetPixels, float side, vec4 colour) {
    gl_Position = clip + vec4(offsetPixels * 2.0 / viewportSize * clip.w, 0.0, 0.0);
    lineColour = colour;
    across = side;
    EmitVertex();
}

void main() {
    vec4 a = gl_in[0].gl_Position;
    vec4 b = gl_in[1].gl_Position;
    vec4 colourA = vertexColour[0];
    vec4 colourB = vertexColour[1];
    // Clip to the near plane first: the division by w below must not see w <= 0.
    float insideA = a.z + a.w;
    float insideB = b.z + b.w;
    if (insideA < 0.0 && insideB < 0.0) {
        return;
    }
    if (insideA < 0.0) {
        float t = insideA / (insideA - insideB);
        a = mix(a, b, t);
        colourA = mix(colourA, colourB, t);
    } else if (insideB < 0.0) {
        float t = insideB / (insideB - insideA);
        b = mix(b, a, t);
        colourB = mix(colourB, colourA, t);
    }
    vec2 screenA = a.xy / a.w * 0.5 * viewportSize;
    vec2 screenB = b.xy / b.w * 0.5 * viewportSize;
    vec2 along = screenB - screenA;
    float pixels = length(along);
    along = pixels > 1e-4 ? along / pixels : vec2(1.0, 0.0);
    float extent = halfWidth + 1.0;
    vec2 normal = vec2(-along.y, along.x) * extent;
    vec2 cap = along * halfWidth;
    emitCorner(a, -normal - cap, -extent, colourA);
    emitCorner(a, normal - cap, extent, colourA);
    emitCorner(b, -normal + cap, -extent, colourB);
    emitCorner(b, normal + cap, extent, colourB);
    EndPrimitive();
}
)";

const char* const kLineBatchFragmentShader = R"(#version 330 core
uniform float halfWidth;
in vec4 lineColour;
noperspective in float across;
out vec4 fragColour;
void main() {
    float coverage = clamp(halfWidth + 0.5 - abs(across), 0.0, 1.0);
    if (coverage <= 0.0) {
        discard;
    }
    fragColour = vec4(lineColour.rgb, lineColour.a * coverage);
}
)";

} // namespace

LineBatch::LineBatch() : buffer_(QOpenGLBuffer::VertexBuffer) {}

LineBatch::~LineBatch() = default;

void LineBatch::setSegments(std::vector<LineVertex> vertices) {
    vertices_ = std::move(vertices);
    dirty_ = true;
}

void LineBatch::initialize() {
    program_ =
        ShaderSources{"lines", kLineBatchVertexShader, kGeometryShader, kLineBatchFragmentShader}
            .build();
    vertexArray_.create();
    buffer_.create();
    buffer_.setUsagePattern(QOpenGLBuffer::StaticDraw);
    QOpenGLVertexArrayObject::Binder binder(&vertexArray_);
    buffer_.bind();
    QOpenGLExtraFunctions* gl = QOpenGLContext::currentContext()->extraFunctions();
    gl->glEnableVertexAttribArray(0);
    gl->glVertexAttribPointer(0, 3, GL_FLOAT, GL_FALSE, sizeof(LineVertex), nullptr);
    gl->glEnableVertexAttribArray(1);
    gl->glVertexAttribPointer(1, 4, GL_FLOAT, GL_FALSE, sizeof(LineVertex),
                              reinterpret_cast<const void*>(sizeof(QVector3D)));
    buffer_.release();
    dirty_ = true;
}

void LineBatch::upload() {
    buffer_.bind();
    buffer_.allocate(vertices_.data(), int(vertices_.size() * sizeof(LineVertex)));
    buffer_.release();
    uploadedCount_ = int(vertices_.size());
    dirty_ = false;
}

void LineBatch::draw(const RenderContext& context) {
    if (!program_) {
        return;
    }
    if (dirty_) {
        upload();
    }
    if (uploadedCount_ == 0) {
        return;
    }
    QOpenGLExtraFunctions& gl = context.gl;
    if (depthTested_) {
        gl.glEnable(GL_DEPTH_TEST);
    } else {
        gl.glDisable(GL_DEPTH_TEST);
    }
    gl.glDepthMask(GL_FALSE); // fringes are translucent: they must not hide what lies behind
    gl.glEnable(GL_BLEND);
    // Colour blends by the line's alpha; the framebuffer's own alpha stays opaque, because Qt
    // composites the viewport into the window by it and a faint line would let the window show
    // through.
    gl.glBlendFuncSeparate(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_ZERO, GL_ONE);

    program_->bind();
    program_->setUniformValue("viewProjection", context.viewProjection);
    program_->setUniformValue("viewportSize", QVector2D(float(context.framebufferSize.width()),
                                                        float(context.framebufferSize.height())));
    program_->setUniformValue("halfWidth", 0.5f * width_ * context.devicePixelRatio);
    QOpenGLVertexArrayObject::Binder binder(&vertexArray_);
    gl.glDrawArrays(GL_LINES, 0, uploadedCount_);
    program_->release();

    gl.glDepthMask(GL_TRUE);
    gl.glDisable(GL_BLEND);
    gl.glEnable(GL_DEPTH_TEST);
}

void LineBatch::release() {
    program_.reset();
    buffer_.destroy();
    vertexArray_.destroy();
    uploadedCount_ = 0;
    dirty_ = true;
}

} // namespace airtrap
