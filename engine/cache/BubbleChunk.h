#pragma once
// The BUBL chunk of a frame file: the trapped air bubbles, the next bubble id, the deletions so
// far and the frame's own creations and deletions per rule (docs/CACHE_FORMAT.md). Kept apart from
// FrameFile so each chunk's layout reads in one place.
#include "bubbles/BubbleState.h"
#include "bubbles/BubbleTally.h"
#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"

#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

class BubbleChunk {
public:
    static constexpr char kTag[] = "BUBL";
    //! u32 id, i32 birth frame, f64 radius, 13 f64 body, 4 f64 (age, floating time, area
    //! fraction, pocket volume).
    static constexpr std::size_t kRecordSize = 2 * sizeof(std::uint32_t) + 18 * sizeof(double);
    //! The deletion rules the chunk counts: the four of its first layout. Later rules are counted
    //! in chunks of their own (BubbleSurfacedChunk), so the layout never changes.
    static constexpr int kStoredRules = BubbleTally::Surfaced;
    //! u32 count, u32 next id, u64 × 4 deletions so far, u64 × 5 the frame's tally.
    static constexpr std::size_t kHeaderSize =
        2 * sizeof(std::uint32_t) + (2 * kStoredRules + 1) * sizeof(std::uint64_t);

    //! What the chunk holds besides the records' count.
    struct Contents {
        std::vector<BubbleState>& bubbles;
        std::uint32_t& nextId;
        BubbleTally& deletedSoFar;
        BubbleTally& frameTally;
    };

    //! Whether a frame needs the chunk: not for scenes that never made a bubble, whose frames
    //! stay byte-identical to those written before bubbles existed.
    static bool needed(const std::vector<BubbleState>& bubbles, std::uint32_t nextId) {
        return !bubbles.empty() || nextId != 0;
    }
    //! The chunk's body (after its tag and length).
    static void write(ByteWriter& out, const std::vector<BubbleState>& bubbles,
                      std::uint32_t nextId, const BubbleTally& deletedSoFar,
                      const BubbleTally& frameTally);
    //! Throws Error(CacheCorrupt) naming `path` when the size does not match the count.
    static void read(const std::uint8_t* data, std::size_t size, const std::string& path,
                     const Contents& into);
};

} // namespace airtrap
