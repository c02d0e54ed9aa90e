#pragma once
// The declarations of the scene's rigid bodies and their keyframes (paper §3.3.1), kept apart from
// the other sections of SceneSections.cpp so that each file reads as one list.
#include "scene/SchemaSection.h"

namespace airtrap {

//! The `bodies` array section: shape, motion, placement, size and material of each body.
SchemaSection bodiesSection();
//! The `keyframes` array section: poses of kinematic bodies at given times.
SchemaSection keyframesSection();

} // namespace airtrap
