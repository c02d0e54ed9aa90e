#pragma once
// The OpenVDB side of WaterVolume. Include only from .cpp files that already pay for OpenVDB's
// headers (they take long to compile: the fewer translation units include them, the better).
#include <openvdb/openvdb.h>

namespace airtrap {

struct WaterGrids {
    openvdb::FloatGrid::Ptr surface;  //!< signed distance, level-set class, negative inside
    openvdb::Vec3SGrid::Ptr velocity; //!< m/s of the nearest particle, over the surface's band
};

} // namespace airtrap
