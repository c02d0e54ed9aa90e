#pragma once
// A free-surface mesh as the post stage stores it beside the cache (`post/water_0001.atm`,
// docs/CACHE_FORMAT.md): magic "ATMS", format version, vertex and triangle counts, float32
// positions, uint32 indices, and a CRC-32 of everything before it. Small and fast to load, so the
// editor can scrub meshes as quickly as particles; exports turn it into OBJ.
#include "rigid/TriangleMesh.h"

#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

class MeshFile {
public:
    static constexpr std::uint32_t kFormatVersion = 1;

    static std::vector<std::uint8_t> encode(const TriangleMesh& mesh);
    //! Checks magic, version, sizes, indices and checksum; any failure → Error(CacheCorrupt)
    //! naming `pathForMessages` and what is wrong.
    static TriangleMesh decode(const std::vector<std::uint8_t>& bytes,
                               const std::string& pathForMessages);

    //! Atomic write (AtomicFile); Error(Io) names `path`.
    static void write(const std::string& path, const TriangleMesh& mesh);
    static TriangleMesh read(const std::string& path);
};

} // namespace airtrap
