#pragma once
#include "scene/Scene.h"

#include <cmath>

namespace airtrap::bench {

//! The sample dam break with the spacing chosen so its water holds about `particles`, and the
//! support at 2 × spacing, the peer setting every benchmark here uses so figures compare.
inline Scene damBreakWith(const Scene& sample, double particles) {
    Scene scene = sample;
    double waterVolume = 0.0;
    for (const FluidBlock& block : scene.fluidBlocks)
        waterVolume += (block.max - block.min).prod();
    scene.solver.particleSpacing = std::cbrt(waterVolume / particles);
    scene.solver.supportFactor = 2.0;
    return scene;
}

} // namespace airtrap::bench
