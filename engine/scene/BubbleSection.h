#pragma once
// The declaration of the scene's trapped air bubble settings (paper §3.2–3.4, Table 1), kept
// apart from SceneSections.cpp so that each file reads as one list.
#include "scene/SchemaSection.h"

namespace airtrap {

//! The `bubbles` object section: creation, dynamics and deletion of trapped air bubbles.
SchemaSection bubblesSection();

} // namespace airtrap
