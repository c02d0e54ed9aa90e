#pragma once
// The scene's rigid bodies as shaded solids, coloured by motion — static grey, dynamic
// red-orange, kinematic blue — and the selected one in the highlight colour. Every body's
// triangles share one buffer, uploaded again only when a body's surface changed (an edit of its
// shape), not when it merely moved (a new frame): poses are uniforms.
#include "document/SceneItem.h"
#include "viewport/Drawable.h"
#include "viewport/SceneBodies.h"

#include <QColor>
#include <QOpenGLBuffer>
#include <QOpenGLShaderProgram>
#include <QOpenGLVertexArrayObject>
#include <memory>
#include <vector>

namespace airtrap {

class BodyDrawable : public Drawable {
public:
    BodyDrawable();
    ~BodyDrawable() override;

    //! Replaces the bodies drawn (surfaces and poses).
    void setBodies(const SceneBodies& bodies);
    //! Draws this item's body in the highlight colour; any other item highlights nothing.
    void setSelection(const SceneItem& item) { selection_ = item; }

    //! The colour of a body with this motion ("static", "dynamic", "kinematic"), before shading.
    static QColor colourOf(const std::string& motion);

    //! Builds the shader and the buffer.
    void initialize() override;
    //! Uploads changed surfaces, then draws every body depth-tested.
    void draw(const RenderContext& context) override;
    //! Frees the GL objects.
    void release() override;

private:
    void upload();

    std::unique_ptr<QOpenGLShaderProgram> program_;
    QOpenGLBuffer buffer_;
    QOpenGLVertexArrayObject vertexArray_;
    SceneBodies bodies_;
    SceneItem selection_;
    //! The surfaces in the buffer, in body order, and where each starts. Held, so that a new
    //! surface can never reuse the address of one in the buffer and go unnoticed.
    std::vector<std::shared_ptr<const SolidMesh>> uploaded_;
    std::vector<int> firstVertex_;
    bool dirty_ = false;
};

} // namespace airtrap
