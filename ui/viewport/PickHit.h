#pragma once
// What a pick ray hit and how far along it, so that gizmos and bodies can be picked together and
// the nearest wins.
#include "document/SceneItem.h"

namespace airtrap {

struct PickHit {
    SceneItem item;
    float distance = 0.0f; //!< m along the ray
};

} // namespace airtrap
