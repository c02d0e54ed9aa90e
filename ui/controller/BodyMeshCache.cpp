#include "controller/BodyMeshCache.h"

#include "core/Error.h"
#include "rigid/MassProperties.h"
#include "sim/BodyBuilder.h"

#include <QDateTime>
#include <QFileInfo>

namespace airtrap {

BodyMeshCache::Entry BodyMeshCache::shapeOf(const Scene& scene, const RigidBodySettings& body) {
    // Primitives are cheap to tessellate; only files are worth keeping.
    if (body.shape == "sphere")
        return {std::make_shared<const SolidMesh>(SolidMesh::sphere(float(body.radius))), {}};
    if (body.shape == "cylinder")
        return {std::make_shared<const SolidMesh>(
                    SolidMesh::cylinder(float(body.radius), float(body.height))),
                {}};
    if (body.shape == "mesh")
        return meshOf(scene, body);
    const Vec3d& size = body.size;
    return {std::make_shared<const SolidMesh>(
                SolidMesh::box(QVector3D(float(size.x()), float(size.y()), float(size.z())))),
            {}};
}

TriangleMesh BodyMeshCache::readMesh(const Scene& scene, const RigidBodySettings& body) {
    return BodyBuilder::loadMesh(scene, body);
}

BodyMeshCache::Entry BodyMeshCache::meshOf(const Scene& scene, const RigidBodySettings& body) {
    const std::string path = BodyBuilder::meshPath(scene, body);
    const QFileInfo file(QString::fromStdString(path));
    const long long modified = file.exists() ? file.lastModified().toMSecsSinceEpoch() : 0;
    const Key key{path, body.meshScale, modified};
    if (const auto found = meshes_.find(key); found != meshes_.end())
        return found->second;
    Entry entry;
    try {
        const TriangleMesh mesh = readMesh(scene, body);
        // Density does not move the centre of mass of a uniform solid.
        entry.centreOfMass = MassProperties::ofMesh(mesh, 1.0).centreOfMass;
        entry.solid = std::make_shared<const SolidMesh>(SolidMesh::fromMesh(mesh));
    } catch (const Error&) {
        // Drawn as nothing; the validator reports the reason before a bake.
    }
    meshes_[key] = entry;
    return entry;
}

} // namespace airtrap
