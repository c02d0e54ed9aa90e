#pragma once
// Wireframe gizmos of the scene: the container (its headroom faintly above the rim), fluid
// blocks in blue, obstacles in grey, emitters in green as their nozzle's disc or rectangle with an
// arrow along the jet. The selected gizmo is drawn thick, in orange, and on
// top of everything so that it stays visible inside the water.
#include "document/SceneItem.h"
#include "viewport/Drawable.h"
#include "viewport/LineBatch.h"
#include "viewport/SceneGizmos.h"

namespace airtrap {

class BoxGizmoDrawable : public Drawable {
public:
    BoxGizmoDrawable();

    //! Replaces the boxes drawn.
    void setGizmos(const SceneGizmos& gizmos);
    //! Highlights this item's box; none (or an item without a box) highlights nothing.
    void setSelection(const SceneItem& item);
    //! Hides the fluid blocks (in playback, where the water has moved on), except a selected one.
    void setFluidBlocksVisible(bool visible);

    //! The colour of the selection highlight.
    static QColor highlightColour() { return QColor(255, 165, 20); }

    //! Builds the line shaders.
    void initialize() override;
    //! Draws the boxes depth-tested, then the highlight over everything.
    void draw(const RenderContext& context) override;
    //! Frees the GL objects.
    void release() override;

private:
    void rebuild();
    static void addBox(std::vector<LineVertex>& vertices, const QVector3D& min,
                       const QVector3D& max, const QColor& colour, float opacity);
    void addGizmo(std::vector<LineVertex>& vertices, const GizmoBox& box, bool selected) const;
    //! The nozzle's outline and an arrow along its jet.
    static void addEmitter(std::vector<LineVertex>& vertices, const GizmoBox& box,
                           const QColor& colour);

    LineBatch boxes_;
    LineBatch highlight_;
    SceneGizmos gizmos_;
    SceneItem selection_;
    bool fluidBlocksVisible_ = true;
};

} // namespace airtrap
