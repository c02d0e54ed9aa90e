#include "cache/BubbleSurroundingsChunk.h"

#include "core/Error.h"

namespace airtrap {

void BubbleSurroundingsChunk::write(ByteWriter& out, const std::vector<BubbleState>& bubbles) {
    out.u32(static_cast<std::uint32_t>(bubbles.size()));
    for (const BubbleState& bubble : bubbles) {
        const BubbleSurroundings& around = bubble.surroundings;
        for (int axis = 0; axis < 3; ++axis)
            out.f64(around.waterVelocity[axis]);
        out.f64(around.impactSpeed);
        out.f64(around.wettedShare);
        out.u8(around.floating ? 1 : 0);
        out.u8(around.measured ? 1 : 0);
    }
}

void BubbleSurroundingsChunk::read(const std::uint8_t* data, std::size_t size,
                                   const std::string& path, std::vector<BubbleState>& bubbles) {
    ByteReader in(data, size, path + ": chunk BSUR");
    const std::uint32_t count = in.u32();
    const std::uint64_t expected = kHeaderSize + std::uint64_t(count) * kRecordSize;
    if (size != expected)
        throw Error(ErrorKind::CacheCorrupt, path + ": chunk BSUR is " + std::to_string(size) +
                                                 " bytes, expected " + std::to_string(expected) +
                                                 " for " + std::to_string(count) + " bubbles");
    if (count != bubbles.size())
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": chunk BSUR describes " + std::to_string(count) +
                        " bubbles but chunk BUBL holds " + std::to_string(bubbles.size()));
    for (BubbleState& bubble : bubbles) {
        BubbleSurroundings& around = bubble.surroundings;
        for (int axis = 0; axis < 3; ++axis)
            around.waterVelocity[axis] = in.f64();
        around.impactSpeed = in.f64();
        around.wettedShare = in.f64();
        around.floating = in.u8() != 0;
        around.measured = in.u8() != 0;
    }
}

} // namespace airtrap
