#include "scene/SceneMigration.h"

#include "core/Error.h"
#include "scene/ParameterCodec.h"
#include "scene/Scene.h"
#include "scene/SceneSchema.h"

namespace airtrap {
namespace {

[[noreturn]] void refuse(const std::string& sourceName, const std::string& message) {
    throw Error(ErrorKind::InvalidScene, sourceName + ": " + message);
}

//! The declared version of `scene`, refused unless it is an integer this build can migrate.
long long checkedVersion(const nlohmann::json& scene, const std::string& sourceName) {
    const ParameterDeclaration& declaration = SceneSchema::formatVersion();
    const std::string expected = ParameterCodec::expectation(declaration);
    if (!scene.contains(declaration.key))
        refuse(sourceName, declaration.key + " is missing; expected " + expected + " (add \"" +
                               declaration.key + "\": " + std::to_string(Scene::kFormatVersion) +
                               " at the top)");
    const nlohmann::json& version = scene[declaration.key];
    if (!version.is_number_integer())
        refuse(sourceName, declaration.key + ": expected " + expected + ", got " + version.dump());
    // Compared as a double so that a huge unsigned version cannot wrap around into range.
    if (version.get<double>() > Scene::kFormatVersion)
        refuse(sourceName, "written by a newer Airtrap (" + declaration.key + " " + version.dump() +
                               "); this build reads format versions up to " +
                               std::to_string(Scene::kFormatVersion) +
                               ". Update Airtrap to open it.");
    if (version.get<double>() < declaration.minimum)
        refuse(sourceName,
               declaration.key + " = " + version.dump() + " is out of range; expected " + expected);
    return version.get<long long>();
}

} // namespace

const std::vector<SceneMigration::Step>& SceneMigration::steps() {
    static const std::vector<Step> steps{};
    return steps;
}

nlohmann::json SceneMigration::toCurrent(nlohmann::json scene, const std::string& sourceName) {
    const std::string& key = SceneSchema::formatVersion().key;
    for (long long version = checkedVersion(scene, sourceName); version < Scene::kFormatVersion;
         ++version) {
        const auto index = static_cast<std::size_t>(version - 1);
        if (index >= steps().size())
            refuse(sourceName, "no migration from format version " + std::to_string(version) +
                                   " to " + std::to_string(version + 1));
        scene = steps()[index](std::move(scene));
        scene[key] = version + 1;
    }
    return scene;
}

} // namespace airtrap
