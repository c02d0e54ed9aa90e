#include "cache/BubbleSurfacedChunk.h"

#include "core/Error.h"

namespace airtrap {

void BubbleSurfacedChunk::write(ByteWriter& out, const BubbleTally& deletedSoFar,
                                const BubbleTally& frameTally) {
    for (const BubbleTally* tally : {&deletedSoFar, &frameTally}) {
        out.u64(tally->deleted[BubbleTally::Surfaced]);
        out.u64(tally->surfacedYoung);
    }
}

void BubbleSurfacedChunk::read(const std::uint8_t* data, std::size_t size, const std::string& path,
                               BubbleTally& deletedSoFar, BubbleTally& frameTally) {
    if (size != kSize)
        throw Error(ErrorKind::CacheCorrupt, path + ": chunk BSFD is " + std::to_string(size) +
                                                 " bytes, expected " + std::to_string(kSize));
    ByteReader in(data, size, path + ": chunk BSFD");
    for (BubbleTally* tally : {&deletedSoFar, &frameTally}) {
        tally->deleted[BubbleTally::Surfaced] = in.u64();
        tally->surfacedYoung = in.u64();
    }
}

} // namespace airtrap
