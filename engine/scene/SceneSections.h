#pragma once
// The declarations themselves, kept apart from SceneSchema's lookups so that the table of
// parameters reads as one list. Use SceneSchema::sections() rather than calling this.
#include "scene/SchemaSection.h"

#include <vector>

namespace airtrap {

//! Builds the sections of the scene schema (see SceneSchema::sections()).
std::vector<SchemaSection> buildSceneSections();

} // namespace airtrap
