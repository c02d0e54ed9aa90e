#pragma once
// Checks that need more than one field: the container's corners, fluid blocks inside it, obstacles
// inside the domain, the particle count, overlaps. Run after reading a scene and after `--set`,
// before baking.
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace airtrap {

//! What SceneValidator found: errors refuse the bake, warnings are shown and the bake goes on.
struct SceneIssues {
    std::vector<std::string> errors;
    std::vector<std::string> warnings;
    bool ok() const { return errors.empty(); }
};

class SceneValidator {
public:
    //! Above this many water particles a bake runs out of memory or patience on a workstation.
    static constexpr double kMaxParticles = 20e6;

    //! Checks every field against its declared range, then the cross-field rules. Messages start
    //! with Scene::sourcePath (or "scene") and name the JSON paths involved.
    static SceneIssues check(const Scene& scene);

    //! The cross-field rules, one sentence each, for docs/SCENE_FORMAT.md.
    static std::vector<std::string> ruleDescriptions();
};

//! Throws Error(InvalidScene) with all errors, one per line; returns the warnings.
std::vector<std::string> validateScene(const Scene& scene);

} // namespace airtrap
