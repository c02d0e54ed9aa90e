#include "sph/BoundaryModel.h"

#include <atomic>
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

namespace airtrap {

BoundaryModel::BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity)
    : static_(gridDomain, cellSize, restDensity), moving_(gridDomain, cellSize, restDensity) {}

void BoundaryModel::rebuild(const std::vector<RigidBody>& bodies) {
    std::vector<std::uint32_t> staticMembers;
    movingMembers_.clear();
    for (std::uint32_t index = 0; index < bodies.size(); ++index)
        (bodies[index].isMoving() ? movingMembers_ : staticMembers).push_back(index);
    if (!staticPlaced_ || staticMembers != staticMembers_) {
        staticMembers_ = std::move(staticMembers);
        static_.rebuild(bodies, staticMembers_);
        staticPlaced_ = true;
    }
    moving_.rebuild(bodies, movingMembers_);
    gatherTerms(bodies);
}

void BoundaryModel::markWaterNearMovingLayer(const NeighborGrid& waterGrid,
                                             const PositionArrays& water, float supportRadius) {
    nearMoving_.assign(waterGrid.sortedCount(), 0);
    // A hair wider than the passes' test, so rounding can only mark more water, never less: a
    // marked particle still checks each distance itself.
    const float radius2 = supportRadius * supportRadius * (1.0f + 1e-4f);
    const auto& positions = moving_.positions();
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, positions.size(), 64), [&](const auto& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b)
            sweepNeighborsAround(waterGrid, water, positions[b], kSkipNone, radius2,
                                 [&](std::uint32_t i, const Vec3f&, float) {
                                     // Many boundary particles mark the same water particle,
                                     // all with the same value.
                                     std::atomic_ref<std::uint8_t>(nearMoving_[i])
                                         .store(1, std::memory_order_relaxed);
                                 });
    });
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
    return static_.allocatedBytes() + moving_.allocatedBytes() +
           terms_.capacity() * sizeof(BodyContactTerms) + nearMoving_.capacity();
}

} // namespace airtrap
