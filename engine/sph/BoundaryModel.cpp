#include "sph/BoundaryModel.h"

namespace airtrap {

BoundaryModel::BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity)
    : restDensity_(restDensity), grid_(gridDomain, cellSize) {}

void BoundaryModel::rebuild(const std::vector<RigidBody>& bodies) {
    std::vector<Vec3f> worldPositions;
    std::vector<Vec3f> worldNormals;
    std::vector<Vec3f> worldVelocities;
    std::vector<float> psi;
    std::vector<std::uint32_t> bodyOf;
    for (std::size_t index = 0; index < bodies.size(); ++index) {
        const RigidBody& body = bodies[index];
        const BoundaryParticles& local = body.boundary();
        for (std::size_t b = 0; b < local.size(); ++b) {
            const Vec3f x = body.toWorld(local.positions[b]);
            worldPositions.push_back(x);
            worldNormals.push_back(body.directionToWorld(local.normals[b]));
            worldVelocities.push_back(body.velocityAt(x));
            psi.push_back(restDensity_ * local.volumes[b]);
            bodyOf.push_back(static_cast<std::uint32_t>(index));
        }
    }
    grid_.build(worldPositions);
    const auto& order = grid_.order();
    const std::size_t n = order.size();
    positions_.resize(n);
    normals_.resize(n);
    velocities_.resize(n);
    psi_.resize(n);
    bodyOf_.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::uint32_t from = order[s];
        positions_[s] = worldPositions[from];
        normals_[s] = worldNormals[from];
        velocities_[s] = worldVelocities[from];
        psi_[s] = psi[from];
        bodyOf_[s] = bodyOf[from];
    }
    gatherTerms(bodies);
}

void BoundaryModel::gatherTerms(const std::vector<RigidBody>& bodies) {
    terms_.resize(bodies.size());
    hasDynamicBodies_ = false;
    for (std::size_t index = 0; index < bodies.size(); ++index) {
        const RigidBody& body = bodies[index];
        BodyContactTerms& terms = terms_[index];
        terms.restitution = static_cast<float>(body.waterMaterial().restitution);
        terms.friction = static_cast<float>(body.waterMaterial().friction);
        terms.dynamic = body.isDynamic();
        terms.centre = body.position();
        terms.inverseMass = body.inertia().inverseMass();
        terms.inverseInertia = body.inertia().inverseInertiaWorld(body.orientation());
        hasDynamicBodies_ = hasDynamicBodies_ || terms.dynamic;
    }
}

std::size_t BoundaryModel::allocatedBytes() const {
    return grid_.allocatedBytes() +
           (positions_.capacity() + normals_.capacity() + velocities_.capacity()) * sizeof(Vec3f) +
           psi_.capacity() * sizeof(float) + bodyOf_.capacity() * sizeof(std::uint32_t);
}

} // namespace airtrap
