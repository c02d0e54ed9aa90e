#pragma once
// The boxes the viewport shows for a scene (container, fluid blocks, obstacles), taken once from
// the Scene so that drawing and picking agree on exactly the same geometry.
#include "document/SceneItem.h"
#include "scene/Scene.h"
#include "viewport/GizmoBox.h"
#include "viewport/PickHit.h"
#include "viewport/Ray.h"

#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace airtrap {

class SceneGizmos {
public:
    //! No gizmos at all.
    SceneGizmos() = default;
    //! The container first, then every fluid block, then every obstacle, in scene order.
    explicit SceneGizmos(const Scene& scene);

    //! Every gizmo box.
    const std::vector<GizmoBox>& boxes() const { return boxes_; }
    //! Metres of simulation domain above the container's rim (drawn faintly).
    float headroom() const { return headroom_; }

    //! What picking may hit, beyond what is always pickable (container and obstacles).
    struct PickOptions {
        bool fluidBlocks = true; //!< false in playback, where the blocks are not drawn
        //! Metres per pixel per metre of depth: turns the edge tolerance into world units.
        float metresPerPixelPerDepth = 0.001f;
        float edgeTolerancePixels = 6.0f; //!< how close to a container edge counts as on it
    };
    //! The gizmo nearest along the ray: solid boxes where the ray enters them, the container
    //! where the ray passes within the tolerance of one of its edges. None when nothing is hit.
    SceneItem pick(const Ray& ray, const PickOptions& options) const;
    //! As pick(), with the distance along the ray, to compare with other things picked.
    std::optional<PickHit> hit(const Ray& ray, const PickOptions& options) const;

    //! The twelve edges of the box [min, max] as pairs of corners.
    static std::array<std::pair<QVector3D, QVector3D>, 12> edgesOf(const QVector3D& min,
                                                                   const QVector3D& max);

    //! The exit of an emitter's nozzle: its disc or rectangle as a closed loop of points.
    static std::vector<QVector3D> nozzleOutline(const InflowEmitterSettings& emitter);

private:
    //! Distance along the ray at which it hits `box`, or a negative number when it misses.
    static float hitDistance(const GizmoBox& box, const Ray& ray, const PickOptions& options);

    std::vector<GizmoBox> boxes_;
    float headroom_ = 0.0f;
};

} // namespace airtrap
