#pragma once
// One trapped air pocket: a connected set of empty neighbour-grid cells the atmosphere does not
// reach (paper §3.4).
#include "core/Math.h"

#include <vector>

namespace airtrap {

struct AirPocket {
    std::vector<int> cells;       //!< linear indices into the neighbour grid
    Vec3d centre = Vec3d::Zero(); //!< m, mean of the cells' centres
    double volume = 0.0;          //!< m³, cells × cell size³
};

} // namespace airtrap
