#pragma once
// The editor's copy of every mesh body's triangles, read once per file (resolved path, scale
// and modification time) and not on every edit or frame. A mesh that cannot be read is
// remembered as unusable too, so a broken file is not read again on every redraw; the scene
// validator tells the user why.
#include "rigid/TriangleMesh.h"
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
    //! body's file read by readMesh() (or taken from the cache).
    Entry shapeOf(const Scene& scene, const RigidBodySettings& body);

    //! Reads and checks a mesh body's file as a bake would (scaled to metres, in its shape
    //! frame). Throws airtrap::Error naming the file and what is wrong with it.
    static TriangleMesh readMesh(const Scene& scene, const RigidBodySettings& body);

private:
    Entry meshOf(const Scene& scene, const RigidBodySettings& body);

    using Key = std::tuple<std::string, double, long long>; // path, scale, modification time
    std::map<Key, Entry> meshes_;
};

} // namespace airtrap
