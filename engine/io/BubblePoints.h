#pragma once
// Bubbles as points for instancing a sphere in a renderer (`bubbles_0001.ply` and
// `subgrid_0001.ply`; docs/CLI.md "export"): binary little-endian PLY 1.0, one `vertex` element
// with float x y z (m), float pscale (radius, m: Houdini's and Blender's instancing scale), float
// vx vy vz (m/s; the velocity v, one property per component as PLY has no vectors), float age (s)
// and uint id (stable for a bubble's life).
#include "core/UpAxis.h"

#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

struct BubblePoint {
    Vec3d position;
    double radius = 0.0;
    Vec3d velocity = Vec3d::Zero();
    double age = 0.0;
    std::uint32_t id = 0;
};

class BubblePoints {
public:
    //! Bytes of one vertex in the binary body: eight floats and the id.
    static constexpr std::size_t kVertexBytes = 8 * sizeof(float) + sizeof(std::uint32_t);

    static std::vector<std::uint8_t> encode(const std::vector<BubblePoint>& points,
                                            const std::vector<std::string>& comments, UpAxis up);
    //! Atomic write (AtomicFile); Error(Io) names `path`.
    static void write(const std::string& path, const std::vector<BubblePoint>& points,
                      const std::vector<std::string>& comments, UpAxis up);
};

} // namespace airtrap
