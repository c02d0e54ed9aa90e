#pragma once
// Turns a scene's `bodies` entry into a RigidBody: its shape, one layer of boundary particles,
// mass properties from density and shape, and its motion (docs/SCENE_FORMAT.md `bodies`).
#include "rigid/MassProperties.h"
#include "rigid/RigidBody.h"
#include "rigid/TriangleMesh.h"
#include "scene/Scene.h"

#include <string>

namespace airtrap {

class CubicSplineKernel;

class BodyBuilder {
public:
    BodyBuilder(const Scene& scene, const CubicSplineKernel& kernel);

    //! Builds scene.bodies[index]. Throws Error(InvalidInput) naming the scene, the body and the
    //! mesh file for a mesh that cannot be used, and for keyframes that do not form a path.
    RigidBody build(std::size_t index) const;

    //! The mesh file of a mesh body, resolved against the scene file's folder.
    static std::string meshPath(const Scene& scene, const RigidBodySettings& body);
    //! `scene` with every mesh path made absolute, for copies of the scene kept elsewhere (the
    //! cache's manifest).
    static Scene withAbsoluteMeshPaths(Scene scene);
    //! Reads and checks a mesh body's mesh, scaled to metres, in its shape frame. A mesh too large
    //! to fit in the domain is refused here, before any work that grows with its size.
    static TriangleMesh loadMesh(const Scene& scene, const RigidBodySettings& body);
    //! The shape of any body, for contact and overlap tests; loads the mesh of a mesh body.
    static BodyShape shapeOf(const Scene& scene, const RigidBodySettings& body, double spacing);
    //! The shape of a loaded mesh, its distance field sampled finely enough for contacts at
    //! `spacing` and reaching 2.5 spacings outside the surface.
    static BodyShape meshShape(const TriangleMesh& mesh, double spacing);

private:
    //! Throws Error(InvalidInput) naming the body's mesh_scale when the mesh is wider than the
    //! domain's diagonal.
    static void checkFitsTheDomain(const Scene& scene, const RigidBodySettings& body,
                                   const TriangleMesh& mesh);
    //! Boundary particles half a spacing inside the surface (shape frame), with volumes.
    BoundaryParticles sampleBoundary(const RigidBodySettings& body, const TriangleMesh* mesh) const;
    MassProperties massOf(const RigidBodySettings& body, const TriangleMesh* mesh) const;
    KinematicMotion kinematicMotionOf(const RigidBodySettings& body) const;

    const Scene& scene_;
    const CubicSplineKernel& kernel_;
    double spacing_;
};

} // namespace airtrap
