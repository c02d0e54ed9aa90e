#pragma once
// How the viewport draws the water's surface mesh: translucent (the default: what lies under the
// water shows through), opaque (the surface's own shape), or as its triangle edges (the mesh's
// resolution and where it is open).
#include <optional>
#include <string_view>

namespace airtrap {

enum class SurfaceShading { Translucent, Opaque, Wireframe };

//! The shading's name on the command line and in the settings: translucent, opaque, wireframe.
constexpr std::string_view surfaceShadingName(SurfaceShading shading) {
    switch (shading) {
    case SurfaceShading::Opaque:
        return "opaque";
    case SurfaceShading::Wireframe:
        return "wireframe";
    case SurfaceShading::Translucent:
        break;
    }
    return "translucent";
}

//! The shading named `name` (as surfaceShadingName() writes it); none for any other text.
constexpr std::optional<SurfaceShading> surfaceShadingNamed(std::string_view name) {
    for (SurfaceShading shading :
         {SurfaceShading::Translucent, SurfaceShading::Opaque, SurfaceShading::Wireframe})
        if (surfaceShadingName(shading) == name)
            return shading;
    return std::nullopt;
}

} // namespace airtrap
