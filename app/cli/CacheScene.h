#pragma once
// The scene a cache was baked from (the manifest's copy), for the verbs that make pictures of a
// bake: post and export. `--set` may change how the bake is rendered (surface_mesh.*,
// bubble_mesh.*, subgrid_bubbles.*), not what was simulated: that would need a new bake.
#include "cache/FrameCache.h"
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace airtrap::cli {

//! Throws Error(InvalidScene) for a manifest scene that does not read back, and for an
//! assignment outside the render settings (naming it and the sections allowed).
Scene cacheScene(const FrameCache& cache, const std::vector<std::string>& renderOverrides);

} // namespace airtrap::cli
