#pragma once
// The scene checks that need the bodies built (docs/SCENE_FORMAT.md "Validation"): a mesh that
// cannot be used, a body reaching outside the domain, and — as warnings, before a bake — bodies
// overlapping the water, an obstacle or each other at t = 0. SceneValidator runs it after the field
// rules pass; it lives here because it builds bodies the way the solver does.
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace airtrap {

class BodyPlacementCheck {
public:
    struct Findings {
        std::vector<std::string> errors;
        std::vector<std::string> warnings;
    };

    //! Messages name the scene's JSON paths (bodies[i] and the body's name) but not the file;
    //! the caller prefixes it.
    static Findings run(const Scene& scene);
};

} // namespace airtrap
