#pragma once
// The water as an OpenVDB file, one per frame (`fluid_0001.vdb`): what the post stage stores and
// what the export writes (docs/CLI.md "export"), with grids named the way renderers look for them
// without renaming:
//   surface  float, level-set class: signed distance in metres, negative inside the water
//   density  float, fog-volume class: 0 outside, rising through the surface's band to 1 inside
//            (Blender's volume shader reads `density`)
//   vel      vec3s, contravariant-relative (velocity) vectors in m/s over the surface's band
//            (motion blur in Houdini, Blender and Arnold)
// File metadata names the units, the up axis and the voxel size; each grid's transform carries
// the voxel size, and for z up a quarter turn about x.
#include "core/UpAxis.h"
#include "post/WaterVolume.h"

#include <string>
#include <utility>
#include <vector>

namespace airtrap {

class WaterVolumeFile {
public:
    using Metadata = std::vector<std::pair<std::string, std::string>>;

    //! Writes the file atomically (AtomicFile); an empty volume gives a file with empty grids, so
    //! a sequence stays whole. Error(Io) names `path`.
    static void write(const std::string& path, const WaterVolume& water, UpAxis up,
                      const Metadata& metadata = {});
    //! Reads a file written with UpAxis::Y back into a volume (`surface` and `vel`). A missing,
    //! truncated or foreign file → Error(CacheCorrupt) naming `path` and what is wrong.
    static WaterVolume read(const std::string& path);
};

} // namespace airtrap
