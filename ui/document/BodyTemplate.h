#pragma once
// The first values of a body added from the editor's menu: a shape of a size that suits the
// scene, placed where it can be seen and will do something — over the middle of the container,
// just above the water — with a name no other body has (keyframes find bodies by name).
#include "rigid/TriangleMesh.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <string>

namespace airtrap {

class BodyTemplate {
public:
    //! A "box", "sphere" or "cylinder" body as the JSON object of a `bodies` element.
    static nlohmann::json primitive(const Scene& scene, const std::string& shape);
    //! A mesh body reading `reference` (as stored in the scene), whose loaded `mesh` (shape
    //! frame, metres) is centred at the usual spot; named after the file.
    static nlohmann::json mesh(const Scene& scene, const std::string& reference,
                               const TriangleMesh& mesh);

    //! Edge of a new box (and diameter of a new sphere or cylinder), m: a fifth of the
    //! container's smallest side, but at least four particle spacings so the water feels it.
    static double defaultExtent(const Scene& scene);
    //! Where a new body `height` metres tall goes: the container's centre in x and z; in y one
    //! particle spacing above the highest water, kept below the container's rim when it fits.
    static Vec3d placement(const Scene& scene, double height);
    //! `base`, or "base 2", "base 3", … — the first name no body of `scene` has.
    static std::string uniqueName(const Scene& scene, const std::string& base);
};

} // namespace airtrap
