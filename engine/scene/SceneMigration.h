#pragma once
// Brings scene JSON written by an older Airtrap up to the current format version, one version at
// a time, before it is read. Format version 1 is the first, so there are no steps yet; a change
// to the format bumps Scene::kFormatVersion and appends the step from the previous version.
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

class SceneMigration {
public:
    //! Rewrites a scene object of format version N into version N + 1.
    using Step = nlohmann::json (*)(nlohmann::json scene);

    //! steps()[N − 1] migrates version N to N + 1; its size is Scene::kFormatVersion − 1.
    static const std::vector<Step>& steps();

    //! Checks `format_version` and migrates `scene` to Scene::kFormatVersion. Throws
    //! Error(InvalidScene) starting with `sourceName` when the version is missing, not an
    //! integer, below 1, or newer than this build reads.
    static nlohmann::json toCurrent(nlohmann::json scene, const std::string& sourceName);
};

} // namespace airtrap
