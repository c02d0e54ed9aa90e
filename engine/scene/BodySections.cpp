#include "scene/BodySections.h"

#include "scene/SchemaBinding.h"

namespace airtrap {
namespace {

using namespace schema;

using BodyAccess = ElementAccess<&Scene::bodies>;
using KeyframeAccess = ElementAccess<&Scene::keyframes>;

ParameterDeclaration rotationDeclaration(std::string help) {
    return {.key = "rotation",
            .label = "Rotation",
            .unit = "°",
            .minimum = -360.0,
            .maximum = 360.0,
            .help = std::move(help)};
}

std::vector<BoundParameter> bodyPlacementParameters() {
    return {
        bind<BodyAccess>({.key = "name",
                          .label = "Name",
                          .minimum = 1,
                          .maximum = kMaxNameLength,
                          .help = "Shown in the scene tree and in messages; keyframes refer to "
                                  "the body by it."},
                         &RigidBodySettings::name),
        bind<BodyAccess>({.key = "shape",
                          .label = "Shape",
                          .help = "Box (size), sphere (radius), cylinder (radius, height along "
                                  "its y axis) or a closed triangle mesh read from a file.",
                          .choices = {"box", "sphere", "cylinder", "mesh"}},
                         &RigidBodySettings::shape),
        bind<BodyAccess>({.key = "motion",
                          .label = "Motion",
                          .help = "Static: never moves. Dynamic: moved by the water, gravity "
                                  "and contacts. Kinematic: follows its keyframes (or its "
                                  "velocities when it has none) and pushes the water.",
                          .choices = {"static", "dynamic", "kinematic"}},
                         &RigidBodySettings::motion),
        bind<BodyAccess>({.key = "position",
                          .label = "Position",
                          .unit = "m",
                          .minimum = -kMaxCoordinate,
                          .maximum = kMaxCoordinate,
                          .help = "Centre of a box, sphere or cylinder; where a mesh's own "
                                  "origin goes."},
                         &RigidBodySettings::position),
        bind<BodyAccess>(rotationDeclaration("Turns about the world x, then y, then z axis, in "
                                             "degrees."),
                         &RigidBodySettings::rotation),
    };
}

std::vector<BoundParameter> bodyShapeParameters() {
    return {
        bind<BodyAccess>({.key = "size",
                          .label = "Size",
                          .unit = "m",
                          .minimum = 0.0,
                          .maximum = kMaxCoordinate,
                          .minimumExclusive = true,
                          .help = "Edge lengths of a box along its x, y and z axes.",
                          .appliesWhenKey = "shape",
                          .appliesWhenValues = {"box"}},
                         &RigidBodySettings::size),
        bind<BodyAccess>({.key = "radius",
                          .label = "Radius",
                          .unit = "m",
                          .minimum = 0.0,
                          .maximum = 100.0,
                          .minimumExclusive = true,
                          .help = "Radius of a sphere or cylinder.",
                          .appliesWhenKey = "shape",
                          .appliesWhenValues = {"sphere", "cylinder"}},
                         &RigidBodySettings::radius),
        bind<BodyAccess>({.key = "height",
                          .label = "Height",
                          .unit = "m",
                          .minimum = 0.0,
                          .maximum = 100.0,
                          .minimumExclusive = true,
                          .help = "Length of a cylinder along its y axis.",
                          .appliesWhenKey = "shape",
                          .appliesWhenValues = {"cylinder"}},
                         &RigidBodySettings::height),
        bind<BodyAccess>({.key = "mesh",
                          .label = "Mesh file",
                          .minimum = 0,
                          .maximum = 4096,
                          .help = "A closed triangle mesh (OBJ, PLY, STL or any format assimp "
                                  "reads), relative to the scene file; shape mesh only.",
                          .appliesWhenKey = "shape",
                          .appliesWhenValues = {"mesh"}},
                         &RigidBodySettings::mesh),
        bind<BodyAccess>({.key = "mesh_scale",
                          .label = "Mesh scale",
                          .minimum = 0.0,
                          .maximum = 1000.0,
                          .minimumExclusive = true,
                          .help = "Multiplies the mesh file's coordinates to give metres.",
                          .appliesWhenKey = "shape",
                          .appliesWhenValues = {"mesh"}},
                         &RigidBodySettings::meshScale),
    };
}

std::vector<BoundParameter> bodyDynamicsParameters() {
    return {
        bind<BodyAccess>({.key = "density",
                          .label = "Density",
                          .unit = "kg/m³",
                          .minimum = 1.0,
                          .maximum = 100000.0,
                          .help = "Of the solid; with its volume it gives mass, centre of mass "
                                  "and inertia. Below the water's rest density a body floats."},
                         &RigidBodySettings::density),
        bind<BodyAccess>({.key = "linear_velocity",
                          .label = "Linear velocity",
                          .unit = "m/s",
                          .minimum = -100.0,
                          .maximum = 100.0,
                          .help = "At t = 0 for a dynamic body; throughout for a kinematic body "
                                  "without keyframes."},
                         &RigidBodySettings::linearVelocity),
        bind<BodyAccess>({.key = "angular_velocity",
                          .label = "Angular velocity",
                          .unit = "rad/s",
                          .minimum = -1000.0,
                          .maximum = 1000.0,
                          .help = "About the world axes through the body's centre; at t = 0 or "
                                  "throughout, as the linear velocity."},
                         &RigidBodySettings::angularVelocity),
        bind<BodyAccess>({.key = "restitution",
                          .label = "Restitution",
                          .minimum = 0.0,
                          .maximum = 1.0,
                          .help = "Share of the approach speed kept after a contact with water "
                                  "or another body (0 = no bounce)."},
                         &RigidBodySettings::restitution),
        bind<BodyAccess>({.key = "friction",
                          .label = "Friction",
                          .minimum = 0.0,
                          .maximum = 2.0,
                          .help = "Coulomb friction coefficient μ of its contacts: the tangential "
                                  "impulse is at most μ times the normal one."},
                         &RigidBodySettings::friction),
    };
}

} // namespace

SchemaSection bodiesSection() {
    std::vector<BoundParameter> parameters = bodyPlacementParameters();
    for (auto group : {bodyShapeParameters(), bodyDynamicsParameters()})
        parameters.insert(parameters.end(), group.begin(), group.end());
    return arraySection<&Scene::bodies>(
        "bodies", "Bodies", "Body",
        "Rigid bodies two-way coupled to the water through the impulse-based boundary force "
        "(paper §3.3.1).",
        std::move(parameters));
}

SchemaSection keyframesSection() {
    return arraySection<&Scene::keyframes>(
        "keyframes", "Keyframes", "Keyframe",
        "Poses of kinematic bodies at given times; a body moves in straight lines between its "
        "keyframes and holds the first and last pose before and after them.",
        {bind<KeyframeAccess>({.key = "body",
                               .label = "Body",
                               .minimum = 1,
                               .maximum = kMaxNameLength,
                               .help = "Name of the kinematic body this pose belongs to."},
                              &BodyKeyframe::body),
         bind<KeyframeAccess>({.key = "time",
                               .label = "Time",
                               .unit = "s",
                               .minimum = 0.0,
                               .maximum = 100000.0,
                               .help = "Simulated time of the pose."},
                              &BodyKeyframe::time),
         bind<KeyframeAccess>({.key = "position",
                               .label = "Position",
                               .unit = "m",
                               .minimum = -kMaxCoordinate,
                               .maximum = kMaxCoordinate,
                               .help = "The body's position at that time."},
                              &BodyKeyframe::position),
         bind<KeyframeAccess>(rotationDeclaration("The body's rotation at that time, as the "
                                                  "body's own rotation."),
                              &BodyKeyframe::rotation)});
}

} // namespace airtrap
