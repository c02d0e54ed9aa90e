#include "scene/SceneOverride.h"

#include "core/Error.h"
#include "scene/ParameterCodec.h"
#include "scene/SceneSchema.h"

namespace airtrap {
namespace {

[[noreturn]] void refuse(const std::string& message) {
    throw Error(ErrorKind::InvalidScene, std::string(kOverrideSource) + ": " + message);
}

} // namespace

void applySceneOverride(Scene& scene, const std::string& assignment) {
    const auto equals = assignment.find('=');
    if (equals == std::string::npos)
        refuse("expected key=value, e.g. solver.particle_spacing=0.02, got \"" + assignment + "\"");
    const ParameterPath path = SceneSchema::resolve(
        ParameterCodec::trimmed(assignment.substr(0, equals)), kOverrideSource);
    const std::size_t count = path.section->elementCount(scene);
    if (path.element >= count)
        refuse(path.section->key + '[' + std::to_string(path.element) + "] does not exist; " +
               path.section->key + " has " + std::to_string(count) +
               (count == 1 ? " element" : " elements"));
    const auto result = ParameterCodec::fromText(path.parameter->declaration,
                                                 assignment.substr(equals + 1), path.text);
    if (!result.ok())
        refuse(result.error);
    path.parameter->set(scene, path.element, result.value);
}

void applySceneOverrides(Scene& scene, const std::vector<std::string>& assignments) {
    Scene changed = scene;
    std::string errors;
    for (const std::string& assignment : assignments) {
        try {
            applySceneOverride(changed, assignment);
        } catch (const Error& error) {
            errors += (errors.empty() ? "" : "\n") + std::string(error.what());
        }
    }
    if (!errors.empty())
        throw Error(ErrorKind::InvalidScene, errors);
    scene = std::move(changed);
}

} // namespace airtrap
