#include "CacheScene.h"

#include "core/Error.h"
#include "scene/SceneJson.h"
#include "scene/SceneOverride.h"

namespace airtrap::cli {

namespace {

bool changesRendering(const std::string& assignment) {
    for (const std::string section : {"surface_mesh.", "bubble_mesh.", "subgrid_bubbles."})
        if (assignment.rfind(section, 0) == 0)
            return true;
    return false;
}

} // namespace

Scene cacheScene(const FrameCache& cache, const std::vector<std::string>& renderOverrides) {
    Scene scene = sceneFromJson(cache.manifest().scene, cache.manifestPath());
    for (const std::string& assignment : renderOverrides)
        if (!changesRendering(assignment))
            throw Error(ErrorKind::InvalidScene,
                        "--set " + assignment +
                            ": only the render settings (surface_mesh.*, bubble_mesh.*, "
                            "subgrid_bubbles.*) can change after a bake; bake again to change "
                            "the simulation");
    applySceneOverrides(scene, renderOverrides);
    return scene;
}

} // namespace airtrap::cli
