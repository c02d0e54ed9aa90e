#pragma once
// The BSFD chunk of a frame file: the bubbles deleted because they left the water (the rule
// `surfaced`, added after the BUBL chunk's layout was fixed), so far and in the frame, and how many
// of them were younger than BubbleTally::kYoungAge (docs/CACHE_FORMAT.md). A frame without it,
// written before the rule existed, reads as none.
#include "bubbles/BubbleTally.h"
#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"

#include <string>

namespace airtrap {

class BubbleSurfacedChunk {
public:
    static constexpr char kTag[] = "BSFD";
    //! u64 × 2 (surfaced, of them young) so far, u64 × 2 the same in the frame.
    static constexpr std::size_t kSize = 4 * sizeof(std::uint64_t);

    static void write(ByteWriter& out, const BubbleTally& deletedSoFar,
                      const BubbleTally& frameTally);
    //! Throws Error(CacheCorrupt) naming `path` when the size is not kSize.
    static void read(const std::uint8_t* data, std::size_t size, const std::string& path,
                     BubbleTally& deletedSoFar, BubbleTally& frameTally);
};

} // namespace airtrap
