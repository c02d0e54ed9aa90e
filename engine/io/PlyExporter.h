#pragma once
// Water particles as a PLY point cloud (one file per frame, `particles_0001.ply`), for Houdini,
// Blender and any tool that reads PLY. Binary little-endian PLY 1.0, one `vertex` element with
// float x y z (m), float vx vy vz (m/s), float density (kg/m³) and uint id (stable across frames).
#include "core/UpAxis.h"
#include "sph/ParticleSet.h"

#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

class PlyExporter {
public:
    //! The whole file: ASCII header (with one `comment` line per entry of `comments`) followed by
    //! the binary body, 32 bytes per particle. Positions and velocities in the `up` frame.
    static std::vector<std::uint8_t> encode(const ParticleSet& particles,
                                            const std::vector<std::string>& comments = {},
                                            UpAxis up = UpAxis::Y);

    //! Writes the file atomically (AtomicFile): a reader never sees half a point cloud. Throws
    //! Error(Io) naming `path`.
    static void write(const std::string& path, const ParticleSet& particles,
                      const std::vector<std::string>& comments = {}, UpAxis up = UpAxis::Y);

    //! "particles_0001.ply": four digits, more from frame 10000 on (docs/CLI.md "export").
    static std::string fileName(int frame);

    //! Bytes of one vertex in the binary body.
    static constexpr std::size_t kVertexBytes = 8 * sizeof(float);
};

} // namespace airtrap
