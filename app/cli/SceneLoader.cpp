#include "SceneLoader.h"

#include "scene/InflowNozzle.h"
#include "scene/SceneJson.h"
#include "scene/SceneOverride.h"
#include "sim/SceneCheck.h"

#include <algorithm>
#include <cmath>

namespace airtrap::cli {

namespace {

bool overlap(const FluidBlock& a, const FluidBlock& b) {
    return (a.min.array() < b.max.array()).all() && (b.min.array() < a.max.array()).all();
}

} // namespace

LoadedScene SceneLoader::load(const std::string& path, const std::vector<std::string>& overrides) {
    LoadedScene loaded{readSceneFile(path), {}, {}};
    applySceneOverrides(loaded.scene, overrides);
    loaded.warnings = validateScene(loaded.scene, &loaded.notes);
    return loaded;
}

ParticleEstimate SceneLoader::estimateParticles(const Scene& scene) {
    ParticleEstimate estimate;
    estimate.exact = scene.obstacles.empty();
    const double dx = scene.solver.particleSpacing;
    const auto& blocks = scene.fluidBlocks;
    for (std::size_t i = 0; i < blocks.size(); ++i) {
        std::size_t count = 1;
        // The same rounding as SceneSetup::fillFluid, so a lone block is counted exactly.
        for (int axis = 0; axis < 3; ++axis) {
            const double size = (blocks[i].max - blocks[i].min)[axis];
            count *= std::size_t(std::max(1L, std::lround(size / dx)));
            // A block thinner than the spacing still gets one layer, which may fall outside.
            if (size < dx)
                estimate.exact = false;
        }
        estimate.count += count;
        for (std::size_t j = 0; j < i; ++j)
            if (overlap(blocks[i], blocks[j]))
                estimate.exact = false;
    }
    // The last step of the bake ends at the end frame's time; layers due before it are emitted.
    const double end = scene.frameTime(scene.frames.endFrame);
    for (const InflowEmitterSettings& settings : scene.emitters) {
        const InflowNozzle nozzle(settings, dx);
        estimate.emitted += nozzle.layersBefore(end) * nozzle.particlesPerLayer();
    }
    return estimate;
}

} // namespace airtrap::cli
