#pragma once
// Water particles as structure-of-arrays. The registry (attributes()) lets the cache, exporters
// and the viewport enumerate the arrays by name without knowing each one; a later attribute
// (bubble radius, age) registers there and is saved and exported with no other change.
#include "core/Math.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

enum class AttributeType : std::uint8_t { Float32 = 1, Vec3Float32 = 2, UInt32 = 3 };

//! Bytes of one element of an attribute of this type.
std::size_t attributeElementSize(AttributeType type);

//! A named, typed view of one particle array (size() elements).
struct ParticleAttribute {
    std::string name;
    AttributeType type;
    void* data;
};

class ParticleSet {
public:
    std::size_t size() const { return positions.size(); }
    bool empty() const { return positions.empty(); }
    void resize(std::size_t count);
    void reserve(std::size_t count);
    void clear() { resize(0); }
    //! Appends one particle; its id is the caller's.
    void push(const Vec3f& position, const Vec3f& velocity, float density, std::uint32_t id);

    //! Views of every stored array, in a fixed order.
    std::vector<ParticleAttribute> attributes();

    //! Heap bytes owned by the arrays (capacity, not size).
    std::size_t allocatedBytes() const;

    bool operator==(const ParticleSet& other) const = default;

    std::vector<Vec3f> positions;   //!< m
    std::vector<Vec3f> velocities;  //!< m/s
    std::vector<float> densities;   //!< kg/m³, evolved by the continuity equation (eq. 2)
    std::vector<std::uint32_t> ids; //!< stable identity across the per-step reordering
};

} // namespace airtrap
