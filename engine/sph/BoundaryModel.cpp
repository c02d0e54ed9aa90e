#include "sph/BoundaryModel.h"

namespace airtrap {

BoundaryModel::BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity)
    : static_(gridDomain, cellSize, restDensity), moving_(gridDomain, cellSize, restDensity) {}

void BoundaryModel::rebuild(const std::vector<RigidBody>& bodies, std::size_t firstBubble) {
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
    gatherTerms(bodies, firstBubble);
}

void BoundaryModel::gatherTerms(const std::vector<RigidBody>& bodies, std::size_t firstBubble) {
    terms_.resize(bodies.size());
    hasDynamicBodies_ = false;
    for (std::size_t index = 0; index < bodies.size(); ++index) {
        const RigidBody& body = bodies[index];
        BodyContactTerms& terms = terms_[index];
        terms.restitution = static_cast<float>(body.waterMaterial().restitution);
        terms.friction = static_cast<float>(body.waterMaterial().friction);
        terms.dynamic = body.isDynamic();
        terms.bubble = index >= firstBubble;
        terms.centre = body.position();
        terms.inverseMass = body.inertia().inverseMass();
        terms.inverseInertia = body.inertia().inverseInertiaWorld(body.orientation());
        terms.linearVelocity = body.linearVelocity();
        terms.angularVelocity = body.angularVelocity();
        terms.volume = body.volume();
        hasDynamicBodies_ = hasDynamicBodies_ || terms.dynamic;
    }
}

std::size_t BoundaryModel::allocatedBytes() const {
    return static_.allocatedBytes() + moving_.allocatedBytes() +
           terms_.capacity() * sizeof(BodyContactTerms) + movingPairs_.allocatedBytes();
}

} // namespace airtrap
