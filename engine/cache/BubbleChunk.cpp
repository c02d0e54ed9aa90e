#include "cache/BubbleChunk.h"

#include "cache/RigidBodyRecord.h"
#include "core/Error.h"

namespace airtrap {

namespace {

void writeDeletions(ByteWriter& out, const BubbleTally& tally) {
    for (int rule = 0; rule < BubbleChunk::kStoredRules; ++rule)
        out.u64(tally.deleted[rule]);
}

void readDeletions(ByteReader& in, BubbleTally& tally) {
    for (int rule = 0; rule < BubbleChunk::kStoredRules; ++rule)
        tally.deleted[rule] = in.u64();
}

} // namespace

void BubbleChunk::write(ByteWriter& out, const std::vector<BubbleState>& bubbles,
                        std::uint32_t nextId, const BubbleTally& deletedSoFar,
                        const BubbleTally& frameTally) {
    out.u32(static_cast<std::uint32_t>(bubbles.size()));
    out.u32(nextId);
    writeDeletions(out, deletedSoFar);
    out.u64(frameTally.created);
    writeDeletions(out, frameTally);
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
                       const Contents& into) {
    ByteReader in(data, size, path + ": chunk BUBL");
    const std::uint32_t count = in.u32();
    into.nextId = in.u32();
    readDeletions(in, into.deletedSoFar);
    into.frameTally.created = in.u64();
    readDeletions(in, into.frameTally);
    // Exact, like BODY: a damaged count must not pass for a newer layout.
    const std::uint64_t expected = kHeaderSize + std::uint64_t(count) * kRecordSize;
    if (size != expected)
        throw Error(ErrorKind::CacheCorrupt, path + ": chunk BUBL is " + std::to_string(size) +
                                                 " bytes, expected " + std::to_string(expected) +
                                                 " for " + std::to_string(count) + " bubbles");
    std::vector<BubbleState>& bubbles = into.bubbles;
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
