#include "viewport/SceneGizmos.h"

#include "scene/InflowNozzle.h"
#include "viewport/QtVectors.h"

#include <cmath>
#include <numbers>

namespace airtrap {

SceneGizmos::SceneGizmos(const Scene& scene) : headroom_(float(scene.container.headroom)) {
    boxes_.push_back({GizmoBox::Kind::Container, SceneItem::sectionItem("container"),
                      toQVector3D(scene.container.min), toQVector3D(scene.container.max)});
    for (std::size_t i = 0; i < scene.fluidBlocks.size(); ++i) {
        const FluidBlock& block = scene.fluidBlocks[i];
        boxes_.push_back({GizmoBox::Kind::FluidBlock, SceneItem::elementItem("fluid_blocks", i),
                          toQVector3D(block.min), toQVector3D(block.max)});
    }
    for (std::size_t i = 0; i < scene.obstacles.size(); ++i) {
        const BoxObstacle& obstacle = scene.obstacles[i];
        const Vec3d half = 0.5 * obstacle.size;
        boxes_.push_back({GizmoBox::Kind::Obstacle, SceneItem::elementItem("obstacles", i),
                          toQVector3D(obstacle.center - half),
                          toQVector3D(obstacle.center + half)});
    }
    for (std::size_t i = 0; i < scene.emitters.size(); ++i) {
        const InflowEmitterSettings& emitter = scene.emitters[i];
        // The exit plane alone would be flat (unpickable, a line seen edge on); a quarter of its
        // size along the jet gives the gizmo a body that shows which way it points.
        const Vec3d exit = InflowNozzle::exitHalfExtent(emitter);
        const Vec3d along = 0.25 * exit.maxCoeff() * emitter.direction.normalized().cwiseAbs();
        const Vec3d half = exit + along;
        GizmoBox box{GizmoBox::Kind::Emitter, SceneItem::elementItem("emitters", i),
                     toQVector3D(emitter.position - half), toQVector3D(emitter.position + half)};
        box.outline = nozzleOutline(emitter);
        box.centre = toQVector3D(emitter.position);
        box.jet = toQVector3D(emitter.direction.normalized() * 2.0 * exit.maxCoeff());
        boxes_.push_back(std::move(box));
    }
}

std::vector<QVector3D> SceneGizmos::nozzleOutline(const InflowEmitterSettings& emitter) {
    Vec3d widthAxis;
    Vec3d heightAxis;
    InflowNozzle::nozzleFrame(emitter.direction, widthAxis, heightAxis);
    std::vector<QVector3D> loop;
    if (emitter.shape == "rectangle") {
        const Vec3d w = 0.5 * emitter.width * widthAxis;
        const Vec3d h = 0.5 * emitter.height * heightAxis;
        const std::array<Vec3d, 4> corners{-w - h, w - h, w + h, -w + h};
        for (const Vec3d& corner : corners)
            loop.push_back(toQVector3D(emitter.position + corner));
        return loop;
    }
    constexpr int kDiscSegments = 48;
    for (int k = 0; k < kDiscSegments; ++k) {
        const double angle = 2.0 * std::numbers::pi * k / kDiscSegments;
        loop.push_back(
            toQVector3D(emitter.position + emitter.radius * (std::cos(angle) * widthAxis +
                                                             std::sin(angle) * heightAxis)));
    }
    return loop;
}

std::array<std::pair<QVector3D, QVector3D>, 12> SceneGizmos::edgesOf(const QVector3D& min,
                                                                     const QVector3D& max) {
    // Corner i takes max on axis k when bit k of i is set.
    auto corner = [&](int i) {
        return QVector3D(i & 1 ? max.x() : min.x(), i & 2 ? max.y() : min.y(),
                         i & 4 ? max.z() : min.z());
    };
    std::array<std::pair<QVector3D, QVector3D>, 12> edges;
    std::size_t count = 0;
    for (int i = 0; i < 8; ++i) {
        for (int bit = 1; bit < 8; bit <<= 1) {
            if (!(i & bit)) {
                edges[count++] = {corner(i), corner(i | bit)};
            }
        }
    }
    return edges;
}

float SceneGizmos::hitDistance(const GizmoBox& box, const Ray& ray, const PickOptions& options) {
    if (box.kind != GizmoBox::Kind::Container) {
        const std::optional<float> hit = ray.hitBox(box.min, box.max);
        return hit ? *hit : -1.0f;
    }
    float nearest = -1.0f;
    for (const auto& [a, b] : edgesOf(box.min, box.max)) {
        const Ray::SegmentApproach approach = ray.approach(a, b);
        const float tolerance =
            options.edgeTolerancePixels * options.metresPerPixelPerDepth * approach.alongRay;
        if (approach.gap <= tolerance && (nearest < 0.0f || approach.alongRay < nearest)) {
            nearest = approach.alongRay;
        }
    }
    return nearest;
}

SceneItem SceneGizmos::pick(const Ray& ray, const PickOptions& options) const {
    const std::optional<PickHit> nearest = hit(ray, options);
    return nearest ? nearest->item : SceneItem::none();
}

std::optional<PickHit> SceneGizmos::hit(const Ray& ray, const PickOptions& options) const {
    std::optional<PickHit> nearest;
    for (const GizmoBox& box : boxes_) {
        if (box.kind == GizmoBox::Kind::FluidBlock && !options.fluidBlocks) {
            continue;
        }
        const float distance = hitDistance(box, ray, options);
        if (distance >= 0.0f && (!nearest || distance < nearest->distance)) {
            nearest = PickHit{box.item, distance};
        }
    }
    return nearest;
}

} // namespace airtrap
