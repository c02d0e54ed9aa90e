#include "scene/SceneSections.h"

#include "core/Error.h"
#include "scene/ParameterCodec.h"

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace airtrap {
namespace {

constexpr double kMaxCoordinate = 1000.0; //!< m; a kilometre is far beyond any sensible tank
constexpr double kMaxNameLength = 200.0;
//! Seeds stay below 2^53 so that they survive any JSON reader that holds numbers as doubles.
constexpr double kMaxSeed = 9007199254740991.0;

// --- Field access: how a section reaches its plain-data object inside a Scene. -------------

struct TopLevelAccess {
    static Scene& of(Scene& scene, std::size_t) { return scene; }
    static const Scene& of(const Scene& scene, std::size_t) { return scene; }
};

template <auto Member>
struct ObjectAccess {
    static auto& of(Scene& scene, std::size_t) { return scene.*Member; }
    static const auto& of(const Scene& scene, std::size_t) { return scene.*Member; }
};

template <auto Member>
struct ElementAccess {
    static auto& of(Scene& scene, std::size_t element) { return (scene.*Member).at(element); }
    static const auto& of(const Scene& scene, std::size_t element) {
        return (scene.*Member).at(element);
    }
};

using SolverAccess = ObjectAccess<&Scene::solver>;
using FramesAccess = ObjectAccess<&Scene::frames>;
using ContainerAccess = ObjectAccess<&Scene::container>;
using FluidBlockAccess = ElementAccess<&Scene::fluidBlocks>;
using ObstacleAccess = ElementAccess<&Scene::obstacles>;
using EmitterAccess = ElementAccess<&Scene::emitters>;
using BodyAccess = ElementAccess<&Scene::bodies>;
using KeyframeAccess = ElementAccess<&Scene::keyframes>;

// --- Conversion between a field and a ParameterValue. ---------------------------------------

[[noreturn]] void kindMismatch(const std::string& key, const ParameterValue& value) {
    throw Error(ErrorKind::InvalidInput,
                "parameter " + key + " cannot hold " + ParameterCodec::formatValue(value));
}

double asReal(const ParameterValue& value, const std::string& key) {
    if (const auto* number = std::get_if<double>(&value))
        return *number;
    if (const auto* integer = std::get_if<long long>(&value))
        return static_cast<double>(*integer);
    kindMismatch(key, value);
}

// Spin boxes hand out doubles for integers too; rounding them is what the user meant.
long long asInteger(const ParameterValue& value, const std::string& key) {
    if (const auto* integer = std::get_if<long long>(&value))
        return *integer;
    if (const auto* number = std::get_if<double>(&value))
        return std::llround(*number);
    kindMismatch(key, value);
}

template <class Held>
const Held& asHeld(const ParameterValue& value, const std::string& key) {
    if (const auto* held = std::get_if<Held>(&value))
        return *held;
    kindMismatch(key, value);
}

ParameterValue toValue(double field) {
    return field;
}
ParameterValue toValue(int field) {
    return static_cast<long long>(field);
}
ParameterValue toValue(std::uint64_t field) {
    return static_cast<long long>(field);
}
ParameterValue toValue(const Vec3d& field) {
    return field;
}
ParameterValue toValue(const std::string& field) {
    return field;
}

void assign(double& field, const ParameterValue& value, const std::string& key) {
    field = asReal(value, key);
}
void assign(int& field, const ParameterValue& value, const std::string& key) {
    field = static_cast<int>(asInteger(value, key));
}
void assign(std::uint64_t& field, const ParameterValue& value, const std::string& key) {
    field = static_cast<std::uint64_t>(asInteger(value, key));
}
void assign(Vec3d& field, const ParameterValue& value, const std::string& key) {
    field = asHeld<Vec3d>(value, key);
}
void assign(std::string& field, const ParameterValue& value, const std::string& key) {
    field = asHeld<std::string>(value, key);
}

//! The kind follows from the field's type, so a declaration cannot disagree with its field; a
//! string field with declared choices is a Choice.
template <class Field>
ParameterKind kindOf(const ParameterDeclaration& declaration) {
    if constexpr (std::is_same_v<Field, std::string>)
        return declaration.choices.empty() ? ParameterKind::String : ParameterKind::Choice;
    else if constexpr (std::is_same_v<Field, double>)
        return ParameterKind::Real;
    else if constexpr (std::is_same_v<Field, Vec3d>)
        return ParameterKind::Vector3;
    else
        return ParameterKind::Int;
}

template <class Access, class Owner, class Field>
BoundParameter bind(ParameterDeclaration declaration, Field Owner::*member) {
    declaration.kind = kindOf<Field>(declaration);
    const std::string key = declaration.key;
    return {std::move(declaration),
            [member](const Scene& scene, std::size_t element) {
                return toValue(Access::of(scene, element).*member);
            },
            [member, key](Scene& scene, std::size_t element, const ParameterValue& value) {
                assign(Access::of(scene, element).*member, value, key);
            }};
}

//! Obstacles are all boxes in format version 1; the key exists so that later versions can add
//! spheres, cylinders and meshes without renaming anything.
BoundParameter obstacleShape() {
    ParameterDeclaration declaration{
        .key = "shape",
        .label = "Shape",
        .kind = ParameterKind::Choice,
        .defaultValue = std::string("box"),
        .help = "Kind of solid; only axis-aligned boxes exist in this version.",
        .choices = {"box"},
    };
    return {std::move(declaration),
            [](const Scene&, std::size_t) -> ParameterValue { return std::string("box"); },
            [](Scene&, std::size_t, const ParameterValue& value) {
                if (asHeld<std::string>(value, "shape") != "box")
                    kindMismatch("shape", value);
            }};
}

// --- The sections. ----------------------------------------------------------------------------

SchemaSection objectSection(std::string key, std::string label, std::string help,
                            std::vector<BoundParameter> parameters) {
    SchemaSection section;
    section.key = std::move(key);
    section.label = std::move(label);
    section.help = std::move(help);
    section.parameters = std::move(parameters);
    section.elementCount = [](const Scene&) -> std::size_t { return 1; };
    section.resize = [](Scene&, std::size_t) {};
    section.insertDefault = [](Scene&, std::size_t) {};
    section.erase = [](Scene&, std::size_t) {};
    return section;
}

template <auto Member>
SchemaSection arraySection(std::string key, std::string label, std::string elementLabel,
                           std::string help, std::vector<BoundParameter> parameters) {
    SchemaSection section =
        objectSection(std::move(key), std::move(label), std::move(help), std::move(parameters));
    section.isArray = true;
    section.elementLabel = std::move(elementLabel);
    section.elementCount = [](const Scene& scene) { return (scene.*Member).size(); };
    section.resize = [](Scene& scene, std::size_t count) { (scene.*Member).resize(count); };
    section.insertDefault = [](Scene& scene, std::size_t index) {
        auto& elements = scene.*Member;
        // An explicit value: `{}` would pick the initializer-list overload and insert nothing.
        using Element = typename std::remove_reference_t<decltype(elements)>::value_type;
        elements.insert(elements.begin() + static_cast<std::ptrdiff_t>(index), Element{});
    };
    section.erase = [](Scene& scene, std::size_t index) {
        auto& elements = scene.*Member;
        elements.erase(elements.begin() + static_cast<std::ptrdiff_t>(index));
    };
    return section;
}

SchemaSection topLevelSection() {
    return objectSection(
        "", "Scene", "Keys at the top level of the file, next to the sections.",
        {bind<TopLevelAccess>({.key = "name",
                               .label = "Scene name",
                               .minimum = 1,
                               .maximum = kMaxNameLength,
                               .defaultValue = std::string("Untitled"),
                               .help = "Shown in the editor's title bar and in the cache."},
                              &Scene::name),
         bind<TopLevelAccess>(
             {.key = "seed",
              .label = "Random seed",
              .minimum = 0,
              .maximum = kMaxSeed,
              .defaultValue = 1LL,
              .help = "Seeds every random choice, so that a bake can be repeated exactly."},
             &Scene::seed)});
}

SchemaSection solverSection() {
    return objectSection(
        "solver", "Solver", "Weakly compressible SPH (WCSPH) settings.",
        {bind<SolverAccess>({.key = "particle_spacing",
                             .label = "Particle spacing",
                             .unit = "m",
                             .minimum = 0.001,
                             .maximum = 1.0,
                             .defaultValue = 0.02,
                             .help = "Initial distance between water particles; halving it "
                                     "gives 8 times as many particles."},
                            &SolverSettings::particleSpacing),
         bind<SolverAccess>({.key = "support_factor",
                             .label = "Support factor",
                             .minimum = 1.5,
                             .maximum = 3.0,
                             .defaultValue = 2.0,
                             .help = "Kernel support radius as a multiple of the particle "
                                     "spacing."},
                            &SolverSettings::supportFactor),
         bind<SolverAccess>({.key = "rest_density",
                             .label = "Rest density",
                             .unit = "kg/m³",
                             .minimum = 100.0,
                             .maximum = 20000.0,
                             .defaultValue = 1000.0,
                             .help = "Density of the liquid at rest (water: 1000)."},
                            &SolverSettings::restDensity),
         bind<SolverAccess>({.key = "max_speed",
                             .label = "Maximum speed",
                             .unit = "m/s",
                             .minimum = 0.1,
                             .maximum = 200.0,
                             .defaultValue = 10.0,
                             .help = "Largest speed expected in the flow; the speed of sound is "
                                     "10 times this, which keeps density errors near 1 %."},
                            &SolverSettings::maxSpeed),
         bind<SolverAccess>({.key = "viscosity_alpha",
                             .label = "Viscosity α",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .defaultValue = 0.1,
                             .help = "Monaghan artificial viscosity between water particles."},
                            &SolverSettings::viscosityAlpha),
         bind<SolverAccess>({.key = "wall_viscosity",
                             .label = "Wall viscosity",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .defaultValue = 0.05,
                             .help = "Artificial viscosity against solid walls, i.e. wall "
                                     "friction."},
                            &SolverSettings::wallViscosity),
         bind<SolverAccess>({.key = "wall_restitution",
                             .label = "Wall restitution",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .defaultValue = 0.0,
                             .help = "Share of the normal speed kept when water hits a wall "
                                     "(0 = no bounce)."},
                            &SolverSettings::wallRestitution),
         bind<SolverAccess>({.key = "cfl_factor",
                             .label = "CFL factor",
                             .minimum = 0.05,
                             .maximum = 0.6,
                             .defaultValue = 0.3,
                             .help = "λ in the time step Δt = λ h / (c + |v|max); smaller is "
                                     "steadier and slower."},
                            &SolverSettings::cflFactor),
         bind<SolverAccess>({.key = "shepard_interval",
                             .label = "Shepard interval",
                             .unit = "steps",
                             .minimum = 0,
                             .maximum = 10000,
                             .defaultValue = 30LL,
                             .help = "Steps between Shepard density re-initialisations (0 = "
                                     "never)."},
                            &SolverSettings::shepardInterval),
         bind<SolverAccess>({.key = "max_density_error",
                             .label = "Maximum density error",
                             .minimum = 0.01,
                             .maximum = 10.0,
                             .defaultValue = 0.2,
                             .help = "The bake stops as blown up when |ρ/ρ₀ − 1| exceeds this "
                                     "anywhere."},
                            &SolverSettings::maxDensityError),
         bind<SolverAccess>({.key = "gravity",
                             .label = "Gravity",
                             .unit = "m/s²",
                             .minimum = -100.0,
                             .maximum = 100.0,
                             .defaultValue = Vec3d(0.0, -9.81, 0.0),
                             .help = "Gravitational acceleration; y is up."},
                            &SolverSettings::gravity)});
}

SchemaSection framesSection() {
    return objectSection(
        "frames", "Frames",
        "Frame rate and range; frame 1 is the initial state at t = 0, frame n is at t = (n − 1) "
        "/ fps.",
        {bind<FramesAccess>({.key = "fps",
                             .label = "Frame rate",
                             .unit = "1/s",
                             .minimum = 1.0,
                             .maximum = 240.0,
                             .defaultValue = 30.0,
                             .help = "Frames per second of simulated time."},
                            &FrameSettings::fps),
         bind<FramesAccess>({.key = "end_frame",
                             .label = "End frame",
                             .minimum = 2,
                             .maximum = 100000,
                             .defaultValue = 60LL,
                             .help = "Last frame to bake."},
                            &FrameSettings::endFrame)});
}

SchemaSection containerSection() {
    return objectSection(
        "container", "Container",
        "The static open-top tank; the simulation domain is the tank plus the headroom above "
        "its rim.",
        {bind<ContainerAccess>({.key = "min",
                                .label = "Minimum corner",
                                .unit = "m",
                                .minimum = -kMaxCoordinate,
                                .maximum = kMaxCoordinate,
                                .defaultValue = Vec3d(0.0, 0.0, 0.0),
                                .help = "Inside corner with the smallest x, y and z (the floor)."},
                               &ContainerSettings::min),
         bind<ContainerAccess>({.key = "max",
                                .label = "Maximum corner",
                                .unit = "m",
                                .minimum = -kMaxCoordinate,
                                .maximum = kMaxCoordinate,
                                .defaultValue = Vec3d(1.0, 1.0, 1.0),
                                .help = "Inside corner with the largest x, y and z (y is the "
                                        "rim)."},
                               &ContainerSettings::max),
         bind<ContainerAccess>({.key = "headroom",
                                .label = "Headroom",
                                .unit = "m",
                                .minimum = 0.0,
                                .maximum = 100.0,
                                .defaultValue = 0.5,
                                .help = "Height above the rim that still belongs to the domain, "
                                        "for splashes."},
                               &ContainerSettings::headroom)});
}

SchemaSection fluidBlocksSection() {
    return arraySection<&Scene::fluidBlocks>(
        "fluid_blocks", "Fluid blocks", "Fluid block",
        "Boxes of water at t = 0, filled on the particle lattice; at least one is needed.",
        {bind<FluidBlockAccess>({.key = "name",
                                 .label = "Name",
                                 .minimum = 1,
                                 .maximum = kMaxNameLength,
                                 .defaultValue = std::string("Water"),
                                 .help = "Shown in the scene tree and in messages."},
                                &FluidBlock::name),
         bind<FluidBlockAccess>({.key = "min",
                                 .label = "Minimum corner",
                                 .unit = "m",
                                 .minimum = -kMaxCoordinate,
                                 .maximum = kMaxCoordinate,
                                 .defaultValue = Vec3d(0.0, 0.0, 0.0),
                                 .help = "Corner with the smallest x, y and z."},
                                &FluidBlock::min),
         bind<FluidBlockAccess>({.key = "max",
                                 .label = "Maximum corner",
                                 .unit = "m",
                                 .minimum = -kMaxCoordinate,
                                 .maximum = kMaxCoordinate,
                                 .defaultValue = Vec3d(0.5, 0.5, 0.5),
                                 .help = "Corner with the largest x, y and z."},
                                &FluidBlock::max),
         bind<FluidBlockAccess>({.key = "initial_velocity",
                                 .label = "Initial velocity",
                                 .unit = "m/s",
                                 .minimum = -100.0,
                                 .maximum = 100.0,
                                 .defaultValue = Vec3d(0.0, 0.0, 0.0),
                                 .help = "Velocity of every particle of the block at t = 0."},
                                &FluidBlock::initialVelocity)});
}

SchemaSection obstaclesSection() {
    return arraySection<&Scene::obstacles>(
        "obstacles", "Obstacles", "Obstacle", "Static solids inside the domain.",
        {bind<ObstacleAccess>({.key = "name",
                               .label = "Name",
                               .minimum = 1,
                               .maximum = kMaxNameLength,
                               .defaultValue = std::string("Obstacle"),
                               .help = "Shown in the scene tree and in messages."},
                              &BoxObstacle::name),
         obstacleShape(),
         bind<ObstacleAccess>({.key = "center",
                               .label = "Centre",
                               .unit = "m",
                               .minimum = -kMaxCoordinate,
                               .maximum = kMaxCoordinate,
                               .defaultValue = Vec3d(0.5, 0.25, 0.5),
                               .help = "Centre of the box."},
                              &BoxObstacle::center),
         bind<ObstacleAccess>({.key = "size",
                               .label = "Size",
                               .unit = "m",
                               .minimum = 0.0,
                               .maximum = kMaxCoordinate,
                               .minimumExclusive = true,
                               .defaultValue = Vec3d(0.2, 0.5, 0.2),
                               .help = "Edge lengths of the box along x, y and z."},
                              &BoxObstacle::size)});
}

SchemaSection emittersSection() {
    return arraySection<&Scene::emitters>(
        "emitters", "Emitters", "Emitter",
        "Inflow nozzles (pouring water): each emits layers of particles on the spacing lattice "
        "from its start time to its stop time, within its particle budget.",
        {bind<EmitterAccess>({.key = "name",
                              .label = "Name",
                              .minimum = 1,
                              .maximum = kMaxNameLength,
                              .defaultValue = std::string("Inflow"),
                              .help = "Shown in the scene tree and in messages."},
                             &InflowEmitterSettings::name),
         bind<EmitterAccess>({.key = "shape",
                              .label = "Shape",
                              .defaultValue = std::string("disc"),
                              .help = "Nozzle cross-section: a disc (radius) or a rectangle "
                                      "(width × height).",
                              .choices = {"disc", "rectangle"}},
                             &InflowEmitterSettings::shape),
         bind<EmitterAccess>({.key = "position",
                              .label = "Position",
                              .unit = "m",
                              .minimum = -kMaxCoordinate,
                              .maximum = kMaxCoordinate,
                              .defaultValue = Vec3d(0.5, 0.8, 0.5),
                              .help = "Centre of the nozzle's exit plane."},
                             &InflowEmitterSettings::position),
         bind<EmitterAccess>({.key = "direction",
                              .label = "Direction",
                              .minimum = -1000.0,
                              .maximum = 1000.0,
                              .defaultValue = Vec3d(0.0, -1.0, 0.0),
                              .help = "Direction of the jet; any length but zero."},
                             &InflowEmitterSettings::direction),
         bind<EmitterAccess>({.key = "radius",
                              .label = "Radius",
                              .unit = "m",
                              .minimum = 0.0,
                              .maximum = 100.0,
                              .minimumExclusive = true,
                              .defaultValue = 0.05,
                              .help = "Radius of a disc nozzle."},
                             &InflowEmitterSettings::radius),
         bind<EmitterAccess>({.key = "width",
                              .label = "Width",
                              .unit = "m",
                              .minimum = 0.0,
                              .maximum = 100.0,
                              .minimumExclusive = true,
                              .defaultValue = 0.1,
                              .help = "Side of a rectangular nozzle along the horizontal "
                                      "perpendicular of the direction (x for a vertical jet)."},
                             &InflowEmitterSettings::width),
         bind<EmitterAccess>({.key = "height",
                              .label = "Height",
                              .unit = "m",
                              .minimum = 0.0,
                              .maximum = 100.0,
                              .minimumExclusive = true,
                              .defaultValue = 0.1,
                              .help = "Side of a rectangular nozzle along the other "
                                      "perpendicular (z for a vertical jet)."},
                             &InflowEmitterSettings::height),
         bind<EmitterAccess>({.key = "speed",
                              .label = "Speed",
                              .unit = "m/s",
                              .minimum = 0.0,
                              .maximum = 200.0,
                              .minimumExclusive = true,
                              .defaultValue = 1.0,
                              .help = "Speed of the emitted water; at most solver.max_speed."},
                             &InflowEmitterSettings::speed),
         bind<EmitterAccess>({.key = "start_time",
                              .label = "Start time",
                              .unit = "s",
                              .minimum = 0.0,
                              .maximum = 100000.0,
                              .defaultValue = 0.0,
                              .help = "Simulated time of the first layer."},
                             &InflowEmitterSettings::startTime),
         bind<EmitterAccess>({.key = "stop_time",
                              .label = "Stop time",
                              .unit = "s",
                              .minimum = 0.0,
                              .maximum = 100000.0,
                              .defaultValue = 1.0,
                              .help = "Nothing is emitted from this simulated time on."},
                             &InflowEmitterSettings::stopTime),
         bind<EmitterAccess>({.key = "max_particles",
                              .label = "Particle budget",
                              .minimum = 1,
                              .maximum = 20000000,
                              .defaultValue = 100000LL,
                              .help = "Most particles this emitter creates; it stops at the last "
                                      "whole layer that fits."},
                             &InflowEmitterSettings::maxParticles)});
}

ParameterDeclaration rotationDeclaration(std::string help) {
    return {.key = "rotation",
            .label = "Rotation",
            .unit = "°",
            .minimum = -360.0,
            .maximum = 360.0,
            .defaultValue = Vec3d(0.0, 0.0, 0.0),
            .help = std::move(help)};
}

std::vector<BoundParameter> bodyPlacementParameters() {
    return {
        bind<BodyAccess>({.key = "name",
                          .label = "Name",
                          .minimum = 1,
                          .maximum = kMaxNameLength,
                          .defaultValue = std::string("Body"),
                          .help = "Shown in the scene tree and in messages; keyframes refer to "
                                  "the body by it."},
                         &RigidBodySettings::name),
        bind<BodyAccess>({.key = "shape",
                          .label = "Shape",
                          .defaultValue = std::string("box"),
                          .help = "Box (size), sphere (radius), cylinder (radius, height along "
                                  "its y axis) or a closed triangle mesh read from a file.",
                          .choices = {"box", "sphere", "cylinder", "mesh"}},
                         &RigidBodySettings::shape),
        bind<BodyAccess>({.key = "motion",
                          .label = "Motion",
                          .defaultValue = std::string("dynamic"),
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
                          .defaultValue = Vec3d(0.5, 0.5, 0.5),
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
                          .defaultValue = Vec3d(0.1, 0.1, 0.1),
                          .help = "Edge lengths of a box along its x, y and z axes."},
                         &RigidBodySettings::size),
        bind<BodyAccess>({.key = "radius",
                          .label = "Radius",
                          .unit = "m",
                          .minimum = 0.0,
                          .maximum = 100.0,
                          .minimumExclusive = true,
                          .defaultValue = 0.05,
                          .help = "Radius of a sphere or cylinder."},
                         &RigidBodySettings::radius),
        bind<BodyAccess>({.key = "height",
                          .label = "Height",
                          .unit = "m",
                          .minimum = 0.0,
                          .maximum = 100.0,
                          .minimumExclusive = true,
                          .defaultValue = 0.1,
                          .help = "Length of a cylinder along its y axis."},
                         &RigidBodySettings::height),
        bind<BodyAccess>({.key = "mesh",
                          .label = "Mesh file",
                          .minimum = 0,
                          .maximum = 4096,
                          .defaultValue = std::string(""),
                          .help = "A closed triangle mesh (OBJ, PLY, STL or any format assimp "
                                  "reads), relative to the scene file; shape mesh only."},
                         &RigidBodySettings::mesh),
        bind<BodyAccess>({.key = "mesh_scale",
                          .label = "Mesh scale",
                          .minimum = 0.0,
                          .maximum = 1000.0,
                          .minimumExclusive = true,
                          .defaultValue = 1.0,
                          .help = "Multiplies the mesh file's coordinates to give metres."},
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
                          .defaultValue = 500.0,
                          .help = "Of the solid; with its volume it gives mass, centre of mass "
                                  "and inertia. Below the water's rest density a body floats."},
                         &RigidBodySettings::density),
        bind<BodyAccess>({.key = "linear_velocity",
                          .label = "Linear velocity",
                          .unit = "m/s",
                          .minimum = -100.0,
                          .maximum = 100.0,
                          .defaultValue = Vec3d(0.0, 0.0, 0.0),
                          .help = "At t = 0 for a dynamic body; throughout for a kinematic body "
                                  "without keyframes."},
                         &RigidBodySettings::linearVelocity),
        bind<BodyAccess>({.key = "angular_velocity",
                          .label = "Angular velocity",
                          .unit = "rad/s",
                          .minimum = -1000.0,
                          .maximum = 1000.0,
                          .defaultValue = Vec3d(0.0, 0.0, 0.0),
                          .help = "About the world axes through the body's centre; at t = 0 or "
                                  "throughout, as the linear velocity."},
                         &RigidBodySettings::angularVelocity),
        bind<BodyAccess>({.key = "restitution",
                          .label = "Restitution",
                          .minimum = 0.0,
                          .maximum = 1.0,
                          .defaultValue = 0.0,
                          .help = "Share of the approach speed kept after a contact with water "
                                  "or another body (0 = no bounce)."},
                         &RigidBodySettings::restitution),
        bind<BodyAccess>({.key = "friction",
                          .label = "Friction",
                          .minimum = 0.0,
                          .maximum = 2.0,
                          .defaultValue = 0.4,
                          .help = "Coulomb friction coefficient μ of its contacts: the tangential "
                                  "impulse is at most μ times the normal one."},
                         &RigidBodySettings::friction),
    };
}

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
                               .defaultValue = std::string("Body"),
                               .help = "Name of the kinematic body this pose belongs to."},
                              &BodyKeyframe::body),
         bind<KeyframeAccess>({.key = "time",
                               .label = "Time",
                               .unit = "s",
                               .minimum = 0.0,
                               .maximum = 100000.0,
                               .defaultValue = 0.0,
                               .help = "Simulated time of the pose."},
                              &BodyKeyframe::time),
         bind<KeyframeAccess>({.key = "position",
                               .label = "Position",
                               .unit = "m",
                               .minimum = -kMaxCoordinate,
                               .maximum = kMaxCoordinate,
                               .defaultValue = Vec3d(0.5, 0.5, 0.5),
                               .help = "The body's position at that time."},
                              &BodyKeyframe::position),
         bind<KeyframeAccess>(rotationDeclaration("The body's rotation at that time, as the "
                                                  "body's own rotation."),
                              &BodyKeyframe::rotation)});
}

} // namespace

std::vector<SchemaSection> buildSceneSections() {
    std::vector<SchemaSection> sections;
    sections.push_back(topLevelSection());
    sections.push_back(solverSection());
    sections.push_back(framesSection());
    sections.push_back(containerSection());
    sections.push_back(fluidBlocksSection());
    sections.push_back(obstaclesSection());
    sections.push_back(emittersSection());
    sections.push_back(bodiesSection());
    sections.push_back(keyframesSection());
    return sections;
}

} // namespace airtrap
