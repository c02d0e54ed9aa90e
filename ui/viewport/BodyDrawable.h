#pragma once
// The scene's rigid bodies as shaded solids, coloured by motion — static grey, dynamic
// red-orange, kinematic blue — and the selected one in the highlight colour. Every body's
// triangles share one buffer, uploaded again only when a body's surface changed (an edit of its
// shape), not when it merely moved (a new frame): poses are uniforms.
#include "document/SceneItem.h"
#include "viewport/GlDrawable.h"
#include "viewport/SceneBodies.h"

#include <QColor>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class BodyDrawable : public GlDrawable {
public:
    BodyDrawable();
    ~BodyDrawable() override;

    //! Replaces the bodies drawn (surfaces and poses).
    void setBodies(const SceneBodies& bodies);
    //! Draws this item's body in the highlight colour; any other item highlights nothing.
    void setSelection(const SceneItem& item) { selection_ = item; }

    //! The colour of a body with this motion ("static", "dynamic", "kinematic"), before shading.
    static QColor colourOf(const std::string& motion);

private:
    ShaderSources shaderSources() const override;
    //! Every body's surface into the one buffer.
    void upload() override;
    bool hasUploaded() const override { return !uploaded_.empty(); }
    //! Every body depth-tested, posed by its uniform.
    void render(const RenderContext& context, QOpenGLShaderProgram& program) override;
    void releaseUploads() override;

    QOpenGLBuffer buffer_;
    SceneBodies bodies_;
    SceneItem selection_;
    //! The surfaces in the buffer, in body order, and where each starts. Held, so that a new
    //! surface can never reuse the address of one in the buffer and go unnoticed.
    std::vector<std::shared_ptr<const SolidMesh>> uploaded_;
    std::vector<int> firstVertex_;
};

} // namespace airtrap
