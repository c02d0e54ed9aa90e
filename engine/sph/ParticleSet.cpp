#include "sph/ParticleSet.h"

namespace airtrap {

std::size_t attributeElementSize(AttributeType type) {
    switch (type) {
    case AttributeType::Float32:
        return sizeof(float);
    case AttributeType::Vec3Float32:
        return 3 * sizeof(float);
    case AttributeType::UInt32:
        return sizeof(std::uint32_t);
    }
    return 0;
}

void ParticleSet::resize(std::size_t count) {
    positions.resize(count);
    velocities.resize(count);
    densities.resize(count);
    ids.resize(count);
}

void ParticleSet::reserve(std::size_t count) {
    positions.reserve(count);
    velocities.reserve(count);
    densities.reserve(count);
    ids.reserve(count);
}

void ParticleSet::push(const Vec3f& position, const Vec3f& velocity, float density,
                       std::uint32_t id) {
    positions.push_back(position);
    velocities.push_back(velocity);
    densities.push_back(density);
    ids.push_back(id);
}

std::vector<ParticleAttribute> ParticleSet::attributes() {
    return {{"position", AttributeType::Vec3Float32, positions.data()},
            {"velocity", AttributeType::Vec3Float32, velocities.data()},
            {"density", AttributeType::Float32, densities.data()},
            {"id", AttributeType::UInt32, ids.data()}};
}

std::size_t ParticleSet::allocatedBytes() const {
    return positions.capacity() * sizeof(Vec3f) + velocities.capacity() * sizeof(Vec3f) +
           densities.capacity() * sizeof(float) + ids.capacity() * sizeof(std::uint32_t);
}

} // namespace airtrap
