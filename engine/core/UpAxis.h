#pragma once
// Exports are in metres with y up, as the simulation is (docs/SCENE_FORMAT.md, docs/CLI.md
// "export"); renderers that want z up (Blender's scene axes, most CAD) get the same picture turned
// a quarter about x: what was up points along +z and what pointed at the viewer (+z) points away
// along +y, a proper rotation, so meshes keep their winding.
#include "core/Math.h"

#include <optional>
#include <string_view>

namespace airtrap {

enum class UpAxis { Y, Z };

//! "y" or "z", as `airtrap-cli export --up` takes it.
constexpr std::string_view upAxisName(UpAxis up) {
    return up == UpAxis::Z ? "z" : "y";
}

//! The axis named `name` (as upAxisName() writes it); none for any other text.
constexpr std::optional<UpAxis> upAxisNamed(std::string_view name) {
    for (UpAxis up : {UpAxis::Y, UpAxis::Z})
        if (upAxisName(up) == name)
            return up;
    return std::nullopt;
}

//! `v` (a position, velocity or normal in the simulation's frame) in the export's frame.
inline Vec3d toExportAxes(const Vec3d& v, UpAxis up) {
    return up == UpAxis::Y ? v : Vec3d(v.x(), -v.z(), v.y());
}

} // namespace airtrap
