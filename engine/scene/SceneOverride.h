#pragma once
// `--set path=value` on the command line: a dotted path into the scene JSON, the same names the
// scene file and the parameter panel use ("solver.particle_spacing=0.02",
// "fluid_blocks[0].max=[1,2,0.5]" or "fluid_blocks[0].max=1,2,0.5", "name=foo").
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace airtrap {

//! The source name that starts every `--set` message.
inline constexpr const char* kOverrideSource = "--set";

//! Applies one assignment, checked like a scene file value. Throws Error(InvalidScene) starting
//! with "--set: " for a malformed assignment, an unknown path (listing the valid keys), an
//! element index beyond the scene's array, or a wrong or out-of-range value.
void applySceneOverride(Scene& scene, const std::string& assignment);

//! Applies all assignments in order. If any fails, `scene` is left unchanged and the error lists
//! every failing assignment, one per line.
void applySceneOverrides(Scene& scene, const std::vector<std::string>& assignments);

} // namespace airtrap
