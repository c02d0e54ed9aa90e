#include "viewport/BoxGizmoDrawable.h"

namespace airtrap {

namespace {

const QColor kContainerColour(205, 205, 215);
const QColor kFluidBlockColour(80, 150, 255);
const QColor kObstacleColour(165, 165, 165);
const QColor kEmitterColour(90, 220, 130);
constexpr float kContainerOpacity = 0.85f;
constexpr float kHeadroomOpacity = 0.3f;
constexpr float kBoxWidth = 1.5f;
constexpr float kHighlightWidth = 3.0f;
//! An emitter's arrowhead: its length and half-width as a share of the arrow's length.
constexpr float kArrowHeadShare = 0.25f;

} // namespace

BoxGizmoDrawable::BoxGizmoDrawable() {
    boxes_.setWidth(kBoxWidth);
    highlight_.setWidth(kHighlightWidth);
    highlight_.setDepthTested(false);
}

void BoxGizmoDrawable::setGizmos(const SceneGizmos& gizmos) {
    gizmos_ = gizmos;
    rebuild();
}

void BoxGizmoDrawable::setSelection(const SceneItem& item) {
    selection_ = item;
    rebuild();
}

void BoxGizmoDrawable::setFluidBlocksVisible(bool visible) {
    fluidBlocksVisible_ = visible;
    rebuild();
}

void BoxGizmoDrawable::addBox(std::vector<LineVertex>& vertices, const QVector3D& min,
                              const QVector3D& max, const QColor& colour, float opacity) {
    for (const auto& [a, b] : SceneGizmos::edgesOf(min, max)) {
        vertices.push_back(LineVertex::at(a, colour, opacity));
        vertices.push_back(LineVertex::at(b, colour, opacity));
    }
}

void BoxGizmoDrawable::addEmitter(std::vector<LineVertex>& vertices, const GizmoBox& box,
                                  const QColor& colour) {
    const auto segment = [&](const QVector3D& a, const QVector3D& b) {
        vertices.push_back(LineVertex::at(a, colour, 1.0f));
        vertices.push_back(LineVertex::at(b, colour, 1.0f));
    };
    for (std::size_t k = 0; k < box.outline.size(); ++k)
        segment(box.outline[k], box.outline[(k + 1) % box.outline.size()]);
    // The jet's arrow, its head in the plane of the jet and the outline's first point.
    const QVector3D tip = box.centre + box.jet;
    segment(box.centre, tip);
    if (box.outline.empty())
        return;
    const QVector3D across =
        (box.outline.front() - box.centre).normalized() * (kArrowHeadShare * box.jet.length());
    const QVector3D back = box.jet * kArrowHeadShare;
    segment(tip, tip - back + across);
    segment(tip, tip - back - across);
}

void BoxGizmoDrawable::addGizmo(std::vector<LineVertex>& vertices, const GizmoBox& box,
                                bool selected) const {
    switch (box.kind) {
    case GizmoBox::Kind::Container: {
        const QColor colour = selected ? highlightColour() : kContainerColour;
        addBox(vertices, box.min, box.max, colour, selected ? 1.0f : kContainerOpacity);
        if (gizmos_.headroom() > 0.0f) {
            // The headroom box shares the rim's edges; drawn faint, it reads as "still domain".
            const QVector3D rim(box.min.x(), box.max.y(), box.min.z());
            const QVector3D top(box.max.x(), box.max.y() + gizmos_.headroom(), box.max.z());
            addBox(vertices, rim, top, colour, kHeadroomOpacity);
        }
        break;
    }
    case GizmoBox::Kind::FluidBlock:
        addBox(vertices, box.min, box.max, selected ? highlightColour() : kFluidBlockColour, 1.0f);
        break;
    case GizmoBox::Kind::Obstacle:
        addBox(vertices, box.min, box.max, selected ? highlightColour() : kObstacleColour, 1.0f);
        break;
    case GizmoBox::Kind::Emitter:
        addEmitter(vertices, box, selected ? highlightColour() : kEmitterColour);
        break;
    }
}

void BoxGizmoDrawable::rebuild() {
    std::vector<LineVertex> plain;
    std::vector<LineVertex> highlighted;
    for (const GizmoBox& box : gizmos_.boxes()) {
        const bool selected = !selection_.isNone() && box.item == selection_;
        if (selected) {
            addGizmo(highlighted, box, true);
        } else if (box.kind != GizmoBox::Kind::FluidBlock || fluidBlocksVisible_) {
            addGizmo(plain, box, false);
        }
    }
    boxes_.setSegments(std::move(plain));
    highlight_.setSegments(std::move(highlighted));
}

void BoxGizmoDrawable::initialize() {
    boxes_.initialize();
    highlight_.initialize();
}

void BoxGizmoDrawable::draw(const RenderContext& context) {
    boxes_.draw(context);
    highlight_.draw(context);
}

void BoxGizmoDrawable::release() {
    boxes_.release();
    highlight_.release();
}

} // namespace airtrap
