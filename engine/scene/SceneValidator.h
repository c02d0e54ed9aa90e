#pragma once
// Checks that need more than one field: the container's corners, fluid blocks inside it, obstacles
// inside the domain, the particle count, overlaps. The checks that need the bodies built come
// after these, in sim/SceneCheck, which is what a bake and `validate` run.
#include "scene/Scene.h"

#include <string>
#include <vector>

namespace airtrap {

//! What SceneValidator found: errors refuse the bake, warnings are shown and the bake goes on.
struct SceneIssues {
    std::vector<std::string> errors;
    std::vector<std::string> warnings;
    //! What the scene does by design that a user may still want to read (a body placed in the
    //! water displaces it): printed, never asked about.
    std::vector<std::string> notes;
    bool ok() const { return errors.empty(); }
};

class SceneValidator {
public:
    //! Above this many water particles a bake runs out of memory or patience on a workstation.
    static constexpr double kMaxParticles = 20e6;

    //! Checks every field against its declared range, then the cross-field rules. Messages start
    //! with Scene::sourcePath (or "scene") and name the JSON paths involved.
    static SceneIssues check(const Scene& scene);

    //! The rule between the surface mesh's sizes (particle radius against the voxel size): its
    //! complaint, or an empty string. The post stage checks settings it is given with it too.
    static std::string surfaceMeshRule(const SurfaceMeshSettings& surface);

    //! The cross-field rules, one sentence each, for docs/SCENE_FORMAT.md; with those of
    //! BodyPlacementCheck (a usable mesh, bodies inside the domain, overlaps at t = 0), which
    //! SceneCheck runs after these.
    static std::vector<std::string> ruleDescriptions();
};

} // namespace airtrap
