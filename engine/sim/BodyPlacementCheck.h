#pragma once
// The scene checks that need the bodies built (docs/SCENE_FORMAT.md "Validation"): a mesh that
// cannot be used, a body reaching outside the domain, as warnings before a bake bodies overlapping
// an obstacle or each other at t = 0 (contacts push them apart with a jolt), and as notes bodies
// placed in the water (the way to float a body: it displaces the water it starts in).
// SceneValidator runs it after the field rules pass; it lives here because it builds bodies the way
// the solver does.
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace airtrap {

class BodyPlacementCheck {
public:
    struct Findings {
        std::vector<std::string> errors;
        std::vector<std::string> warnings;
        std::vector<std::string> notes;
    };

    //! Messages name the scene's JSON paths (bodies[i] and the body's name) but not the file;
    //! the caller prefixes it.
    static Findings run(const Scene& scene);
};

} // namespace airtrap
