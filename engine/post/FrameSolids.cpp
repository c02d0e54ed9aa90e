#include "post/FrameSolids.h"

#include <algorithm>
#include <limits>

namespace airtrap {

FrameSolids::FrameSolids(const SceneSolids& solids, const SimulationState& state) {
    for (std::size_t i = 0; i < solids.solids().size(); ++i)
        placed_.push_back({&solids.solids()[i], solids.poseIn(i, state)});
    for (const BubbleState& bubble : state.bubbles)
        bubbles_.push_back({bubble.body.position, bubble.radius});
}

double FrameSolids::clearance(const Vec3d& x) const {
    double nearest = std::numeric_limits<double>::infinity();
    for (const Sphere& bubble : bubbles_)
        nearest = std::min(nearest, (x - bubble.centre).norm() - bubble.radius);
    for (const PlacedSolid& placed : placed_) {
        const Vec3d offset = x - placed.pose.position;
        // No solid reaches beyond its bounding sphere: a far one cannot be the nearest.
        if (offset.norm() - placed.solid->shape.boundingRadius() >= nearest)
            continue;
        const Vec3d local = placed.pose.orientation.conjugate() * offset;
        nearest = std::min(nearest, placed.solid->shape.signedDistance(local));
    }
    return nearest;
}

std::vector<NamedMesh> FrameSolids::meshes() const {
    std::vector<NamedMesh> meshes;
    for (const PlacedSolid& placed : placed_)
        if (!placed.solid->mesh.vertices.empty())
            meshes.push_back(
                {placed.solid->name, placed.solid->mesh.transformed(1.0, placed.pose.orientation,
                                                                    placed.pose.position)});
    return meshes;
}

} // namespace airtrap
