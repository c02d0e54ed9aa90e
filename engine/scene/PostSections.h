#pragma once
// The declarations of the render outputs' settings (paper §4.1–4.2; docs/SCENE_FORMAT.md
// `surface_mesh`, `bubble_mesh`, `subgrid_bubbles`). They shape what the post stage makes of a
// bake, not the bake, so the cache's parameter hash leaves them out: changing them never asks for a
// re-bake.
#include "scene/SchemaSection.h"

namespace airtrap {

//! The `surface_mesh` object section: the free-surface water mesh.
SchemaSection surfaceMeshSection();
//! The `bubble_mesh` object section: the oscillating bubble mesh.
SchemaSection bubbleMeshSection();
//! The `subgrid_bubbles` object section: bubbles below the grid's resolution.
SchemaSection subgridBubblesSection();

} // namespace airtrap
