#include "cache/BubbleChunk.h"

#include "cache/RigidBodyRecord.h"
#include "core/Error.h"

namespace airtrap {

void BubbleChunk::write(ByteWriter& out, const std::vector<BubbleState>& bubbles,
                        std::uint32_t nextId) {
    out.u32(static_cast<std::uint32_t>(bubbles.size()));
    out.u32(nextId);
    for (const BubbleState& bubble : bubbles) {
        out.u32(bubble.id);
        out.i32(bubble.birthFrame);
        out.f64(bubble.radius);
        RigidBodyRecord::write(out, bubble.body);
        out.f64(bubble.age);
        out.f64(bubble.floatingTime);
        out.f64(bubble.areaFractionInWater);
        out.f64(bubble.pocketVolume);
    }
}

void BubbleChunk::read(const std::uint8_t* data, std::size_t size, const std::string& path,
                       std::vector<BubbleState>& bubbles, std::uint32_t& nextId) {
    ByteReader in(data, size, path + ": chunk BUBL");
    const std::uint32_t count = in.u32();
    nextId = in.u32();
    // Exact, like BODY: a damaged count must not pass for a newer layout.
    const std::uint64_t expected = 2 * sizeof(std::uint32_t) + std::uint64_t(count) * kRecordSize;
    if (size != expected)
        throw Error(ErrorKind::CacheCorrupt, path + ": chunk BUBL is " + std::to_string(size) +
                                                 " bytes, expected " + std::to_string(expected) +
                                                 " for " + std::to_string(count) + " bubbles");
    bubbles.clear();
    bubbles.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        BubbleState bubble;
        bubble.id = in.u32();
        bubble.birthFrame = in.i32();
        bubble.radius = in.f64();
        bubble.body = RigidBodyRecord::read(in);
        bubble.age = in.f64();
        bubble.floatingTime = in.f64();
        bubble.areaFractionInWater = in.f64();
        bubble.pocketVolume = in.f64();
        bubbles.push_back(bubble);
    }
}

} // namespace airtrap
