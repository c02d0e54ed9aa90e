#pragma once
// The whole check of a scene before a bake: SceneValidator's rules on the fields, then, when they
// pass, BodyPlacementCheck's on the bodies built as the solver builds them. The command line and
// the editor validate through this; SceneValidator alone knows nothing of built bodies, being a
// layer below them (docs/ARCHITECTURE.md).
#include "scene/SceneValidator.h"

#include <string>
#include <vector>

namespace airtrap {

class SceneCheck {
public:
    //! Messages start with Scene::sourcePath (or "scene") and name the JSON paths involved.
    static SceneIssues run(const Scene& scene);
};

//! Throws Error(InvalidScene) with all of SceneCheck's errors, one per line; returns the
//! warnings, and the notes into `notes` when given.
std::vector<std::string> validateScene(const Scene& scene,
                                       std::vector<std::string>* notes = nullptr);

} // namespace airtrap
