#include "sph/BoundaryModel.h"

namespace airtrap {

BoundaryModel::BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity)
    : restDensity_(restDensity), grid_(gridDomain, cellSize) {}

void BoundaryModel::rebuild(const std::vector<RigidBody>& bodies) {
    std::vector<Vec3f> worldPositions;
    std::vector<Vec3f> worldNormals;
    std::vector<Vec3f> worldVelocities;
    std::vector<float> psi;
    for (const RigidBody& body : bodies) {
        const BoundaryParticles& local = body.boundary();
        for (std::size_t b = 0; b < local.size(); ++b) {
            const Vec3f x = body.toWorld(local.positions[b]);
            worldPositions.push_back(x);
            worldNormals.push_back(body.directionToWorld(local.normals[b]));
            worldVelocities.push_back(body.velocityAt(x));
            psi.push_back(restDensity_ * local.volumes[b]);
        }
    }
    grid_.build(worldPositions);
    const auto& order = grid_.order();
    const std::size_t n = order.size();
    positions_.resize(n);
    normals_.resize(n);
    velocities_.resize(n);
    psi_.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::uint32_t from = order[s];
        positions_[s] = worldPositions[from];
        normals_[s] = worldNormals[from];
        velocities_[s] = worldVelocities[from];
        psi_[s] = psi[from];
    }
}

std::size_t BoundaryModel::allocatedBytes() const {
    return grid_.allocatedBytes() +
           (positions_.capacity() + normals_.capacity() + velocities_.capacity()) * sizeof(Vec3f) +
           psi_.capacity() * sizeof(float);
}

} // namespace airtrap
