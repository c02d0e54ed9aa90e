#include "post/SceneSolids.h"

#include "post/ShapeTessellation.h"
#include "rigid/EulerRotation.h"
#include "rigid/MassProperties.h"
#include "sim/BodyBuilder.h"

namespace airtrap {

SceneSolids::SceneSolids(const Scene& scene) {
    solids_.push_back({.name = "Container",
                       .shape = BodyShape::tank({scene.container.min, scene.container.max}),
                       .mesh = {},
                       .centreOfMass = Vec3d::Zero(),
                       .scenePose = {}});
    for (const BoxObstacle& obstacle : scene.obstacles)
        solids_.push_back({.name = obstacle.name,
                           .shape = BodyShape::box(obstacle.size),
                           .mesh = tessellateBox(obstacle.size),
                           .centreOfMass = Vec3d::Zero(),
                           .scenePose = {obstacle.center, Quatd::Identity()}});
    for (std::size_t index = 0; index < scene.bodies.size(); ++index)
        addBody(scene, index);
}

void SceneSolids::addBody(const Scene& scene, std::size_t index) {
    const RigidBodySettings& body = scene.bodies[index];
    const double spacing = scene.solver.particleSpacing;
    TriangleMesh mesh;
    if (body.shape == "mesh")
        mesh = BodyBuilder::loadMesh(scene, body);
    else if (body.shape == "sphere")
        mesh = tessellateSphere(body.radius);
    else if (body.shape == "cylinder")
        mesh = tessellateCylinder(body.radius, body.height);
    else
        mesh = tessellateBox(body.size);
    BodyShape shape = body.shape == "mesh" ? BodyBuilder::meshShape(mesh, spacing)
                                           : BodyBuilder::shapeOf(scene, body, spacing);
    // A primitive is centred on its centre of mass; a mesh's lies wherever its file puts it.
    const Vec3d centreOfMass =
        body.shape == "mesh" ? MassProperties::ofMesh(mesh, 1.0).centreOfMass : Vec3d::Zero();
    solids_.push_back({.name = body.name,
                       .shape = std::move(shape),
                       .mesh = std::move(mesh),
                       .centreOfMass = centreOfMass,
                       .dynamic = body.motion == "dynamic",
                       .stateIndex = int(index),
                       .scenePose = {body.position, EulerRotation::fromDegrees(body.rotation)}});
}

RigidPose SceneSolids::poseIn(std::size_t index, const SimulationState& state) const {
    const Solid& solid = solids_.at(index);
    if (solid.stateIndex < 0 || std::size_t(solid.stateIndex) >= state.bodies.size())
        return solid.scenePose;
    const RigidBodyState& body = state.bodies[std::size_t(solid.stateIndex)];
    const Vec3d origin = solid.dynamic
                             ? Vec3d(body.position - body.orientation * solid.centreOfMass)
                             : body.position;
    return {origin, body.orientation};
}

} // namespace airtrap
