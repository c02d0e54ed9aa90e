#pragma once
// The viewport's copy of every mesh body's triangles, read once per file (resolved path, scale
// and modification time) and not on every edit or frame. A mesh that cannot be read is
// remembered as unusable too, so a broken file is not read again on every redraw; the scene
// validator tells the user why.
#include "scene/Scene.h"
#include "viewport/SolidMesh.h"

#include <map>
#include <memory>
#include <string>
#include <tuple>

namespace airtrap {

class BodyMeshCache {
public:
    struct Entry {
        std::shared_ptr<const SolidMesh> solid; //!< null when the mesh cannot be used
        Vec3d centreOfMass = Vec3d::Zero();     //!< shape frame
    };

    //! The surface of `body` of `scene` and its centre of mass: a tessellated primitive, or a mesh
    //! body's file loaded through BodyBuilder::loadMesh (or taken from the cache).
    Entry shapeOf(const Scene& scene, const RigidBodySettings& body);

private:
    Entry meshOf(const Scene& scene, const RigidBodySettings& body);

    using Key = std::tuple<std::string, double, long long>; // path, scale, modification time
    std::map<Key, Entry> meshes_;
};

} // namespace airtrap
