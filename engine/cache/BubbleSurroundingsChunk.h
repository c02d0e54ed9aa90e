#pragma once
// The BSUR chunk of a frame file: each bubble's surroundings as last measured, in the order of
// the BUBL chunk's records (docs/CACHE_FORMAT.md). The measure is taken every few steps, so a
// resumed bake needs the last one to take the same steps as a bake that ran on. A frame without
// the chunk (written before it existed) reads as bubbles not yet measured.
#include "bubbles/BubbleState.h"
#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"

#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

class BubbleSurroundingsChunk {
public:
    static constexpr char kTag[] = "BSUR";
    //! f64 × 3 water velocity, f64 impact speed, f64 wetted share, u8 floating, u8 measured.
    static constexpr std::size_t kRecordSize = 5 * sizeof(double) + 2 * sizeof(std::uint8_t);
    //! u32 count.
    static constexpr std::size_t kHeaderSize = sizeof(std::uint32_t);

    //! The chunk's body (after its tag and length).
    static void write(ByteWriter& out, const std::vector<BubbleState>& bubbles);
    //! Fills the surroundings of `bubbles`, read from BUBL before. Throws Error(CacheCorrupt)
    //! naming `path` when the size does not match the count or the count not the bubbles'.
    static void read(const std::uint8_t* data, std::size_t size, const std::string& path,
                     std::vector<BubbleState>& bubbles);
};

} // namespace airtrap
