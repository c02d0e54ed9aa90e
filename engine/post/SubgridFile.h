#pragma once
// A frame's sub-grid bubbles as the post stage stores them beside the cache
// (`post/subgrid_0001.atb`, docs/CACHE_FORMAT.md): magic "ATSB", format version, the two ids the
// next frame goes on from, the bubble count, per bubble its id, parent id, generation, position,
// radius, velocity and age (float64 where the next frame's step starts from them), and a CRC-32
// of everything before it. The next frame's bubbles are advanced from these, so they are kept at
// full precision.
#include "post/SubgridFrame.h"

#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

class SubgridFile {
public:
    static constexpr std::uint32_t kFormatVersion = 1;

    static std::vector<std::uint8_t> encode(const SubgridFrame& frame);
    //! Checks magic, version, size and checksum; any failure → Error(CacheCorrupt) naming
    //! `pathForMessages` and what is wrong.
    static SubgridFrame decode(const std::vector<std::uint8_t>& bytes,
                               const std::string& pathForMessages);

    //! Atomic write (AtomicFile); Error(Io) names `path`.
    static void write(const std::string& path, const SubgridFrame& frame);
    static SubgridFrame read(const std::string& path);
};

} // namespace airtrap
