#include "sph/BoundaryContact.h"

#include <algorithm>

namespace airtrap {

Vec3f BoundaryContact::impulse(const Vec3f& velocity, const Vec3f& acceleration,
                               const Nearest& contact, const BoundaryModel& boundary,
                               float dt) const {
    const std::size_t b = static_cast<std::size_t>(contact.boundaryParticle);
    const BoundaryLayer& layer = *contact.layer;
    const Vec3f& normal = layer.normals()[b];
    const Vec3f predicted = velocity + dt * acceleration - layer.velocities()[b];
    const float normalSpeed = predicted.dot(normal);
    if (normalSpeed >= 0.0f)
        return Vec3f::Zero();
    const BodyContactTerms& body = boundary.contactTerms(layer.bodyOf()[b]);
    const Vec3d x = layer.positions()[b].cast<double>();
    const double inverseWaterMass = 1.0 / waterMass_;
    const auto effectiveMass = [&](const Vec3f& direction) {
        return 1.0 / (inverseWaterMass + body.inverseEffectiveMass(x, direction.cast<double>()));
    };
    const float normalImpulse =
        static_cast<float>(-(1.0 + body.restitution) * normalSpeed * effectiveMass(normal));
    Vec3f impulse = normalImpulse * normal;
    const Vec3f slip = predicted - normalSpeed * normal;
    const float slipSpeed = slip.norm();
    if (body.friction > 0.0f && slipSpeed > 0.0f) {
        const Vec3f tangent = slip / slipSpeed;
        const float stopping = static_cast<float>(slipSpeed * effectiveMass(tangent));
        impulse -= std::min(body.friction * normalImpulse, stopping) * tangent;
    }
    return impulse;
}

void BoundaryContact::record(std::size_t i, const Nearest& contact, const Vec3f& impulse,
                             const BoundaryModel& boundary, ContactRecords& contacts) {
    const bool onDynamicBody =
        contact.boundaryParticle >= 0 &&
        boundary.contactTerms(contact.layer->bodyOf()[contact.boundaryParticle]).dynamic &&
        impulse != Vec3f::Zero();
    contacts.boundaryParticle[i] =
        onDynamicBody ? static_cast<std::int32_t>(contact.boundaryParticle) : -1;
    // Read only where a boundary particle is recorded: most of the water skips the write.
    if (onDynamicBody)
        contacts.impulse[i] = impulse;
}

} // namespace airtrap
