#pragma once
// The move gizmo: three arrows along the world axes (x red, y green, z blue) at the selected
// object's centre, drawn over everything at a fixed size on screen. Dragging an arrow slides the
// object along that axis: the offset is where the cursor's ray passes nearest the axis line,
// measured from where the drag began, rounded to a millimetre. Plain math and a line batch; the
// viewport routes the mouse to it and reports the offsets.
#include "viewport/Drawable.h"
#include "viewport/LineBatch.h"
#include "viewport/OrbitCamera.h"

#include <QPointF>
#include <QSize>
#include <QVector3D>
#include <optional>

namespace airtrap {

class MoveGizmo : public Drawable {
public:
    MoveGizmo();

    //! Where the arrows stand; none hides them (nothing movable selected).
    void setOrigin(std::optional<QVector3D> origin);
    const std::optional<QVector3D>& origin() const { return origin_; }
    //! The arrows' length, m.
    float armLength() const { return armLength_; }
    //! Sizes the arrows for this view: a fixed share of its height.
    void fitTo(const OrbitCamera& camera, const QSize& size);

    //! The axis (0 x, 1 y, 2 z) whose arrow is under `pixel`; none when no arrow is near.
    std::optional<int> axisAt(const QPointF& pixel, const OrbitCamera& camera,
                              const QSize& size) const;
    //! A drag of `axis`'s arrow starts at `pixel`. False when the axis points at the eye (no
    //! motion along it can be read from the screen).
    bool beginDrag(int axis, const QPointF& pixel, const OrbitCamera& camera, const QSize& size);
    //! Metres along the dragged axis from where the drag began, rounded to a millimetre.
    double dragOffset(const QPointF& pixel, const OrbitCamera& camera, const QSize& size) const;
    void endDrag();
    std::optional<int> draggedAxis() const { return dragAxis_; }

    void initialize() override;
    void draw(const RenderContext& context) override;
    void release() override;

private:
    //! Where along `axis` (metres from the origin) the ray through `pixel` passes nearest it;
    //! none when the ray runs (nearly) parallel to the axis.
    std::optional<double> axisParameter(int axis, const QPointF& pixel, const OrbitCamera& camera,
                                        const QSize& size) const;
    void rebuild();

    std::optional<QVector3D> origin_;
    float armLength_ = 0.1f; //!< m
    std::optional<int> dragAxis_;
    double dragStart_ = 0.0; //!< axis parameter where the drag began, m
    LineBatch lines_;
};

} // namespace airtrap
