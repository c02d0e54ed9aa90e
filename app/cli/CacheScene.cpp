#include "CacheScene.h"

#include "core/Error.h"
#include "scene/ParameterCodec.h"
#include "scene/SceneJson.h"
#include "scene/SceneOverride.h"
#include "scene/SceneSchema.h"

namespace airtrap::cli {

namespace {

//! Whether `assignment` ("surface_mesh.smoothing=2") sets a render setting. A malformed one or
//! an unknown key is let through: applySceneOverrides says what is wrong with it.
bool changesRendering(const std::string& assignment) {
    const std::string path = ParameterCodec::trimmed(assignment.substr(0, assignment.find('=')));
    try {
        return SceneSchema::resolve(path, kOverrideSource).section->renderSetting;
    } catch (const Error&) {
        return true;
    }
}

//! "surface_mesh.*, bubble_mesh.*, subgrid_bubbles.*", from the schema.
std::string renderSettings() {
    std::string list;
    for (const SchemaSection& section : SceneSchema::sections())
        if (section.renderSetting)
            list += (list.empty() ? "" : ", ") + section.key + ".*";
    return list;
}

} // namespace

Scene cacheScene(const FrameCache& cache, const std::vector<std::string>& renderOverrides) {
    Scene scene = sceneFromJson(cache.manifest().scene, cache.manifestPath());
    for (const std::string& assignment : renderOverrides)
        if (!changesRendering(assignment))
            throw Error(ErrorKind::InvalidScene,
                        "--set " + assignment + ": only the render settings (" + renderSettings() +
                            ") can change after a bake; bake again to change the simulation");
    applySceneOverrides(scene, renderOverrides);
    return scene;
}

} // namespace airtrap::cli
