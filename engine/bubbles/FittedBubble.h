#pragma once
// A bubble sized to fit an air pocket (paper §3.4), before it becomes a rigid body.
#include "core/Math.h"

namespace airtrap {

struct FittedBubble {
    Vec3d centre = Vec3d::Zero();
    double radius = 0.0;       //!< m
    double pocketVolume = 0.0; //!< m³
};

} // namespace airtrap
