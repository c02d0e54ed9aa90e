#include "scene/SceneSections.h"

#include "scene/BodySections.h"
#include "scene/BubbleSection.h"
#include "scene/PostSections.h"
#include "scene/SchemaBinding.h"

namespace airtrap {
namespace {

//! Seeds stay below 2^53 so that they survive any JSON reader that holds numbers as doubles.
constexpr double kMaxSeed = 9007199254740991.0;

using namespace schema;

using SolverAccess = ObjectAccess<&Scene::solver>;
using FramesAccess = ObjectAccess<&Scene::frames>;
using ContainerAccess = ObjectAccess<&Scene::container>;
using FluidBlockAccess = ElementAccess<&Scene::fluidBlocks>;
using ObstacleAccess = ElementAccess<&Scene::obstacles>;
using EmitterAccess = ElementAccess<&Scene::emitters>;

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

SchemaSection topLevelSection() {
    return objectSection(
        "", "Scene", "Keys at the top level of the file, next to the sections.",
        {bind<TopLevelAccess>({.key = "name",
                               .label = "Scene name",
                               .minimum = 1,
                               .maximum = kMaxNameLength,
                               .help = "Shown in the editor's title bar and in the cache."},
                              &Scene::name),
         bind<TopLevelAccess>(
             {.key = "seed",
              .label = "Random seed",
              .minimum = 0,
              .maximum = kMaxSeed,
              .help = "Seeds every random choice, so that a bake can be repeated exactly."},
             &Scene::seed)});
}

SchemaSection solverSection() {
    return objectSection(
        "solver", "Solver",
        "The water's solver: weakly compressible SPH (WCSPH, the paper's) or divergence-free SPH "
        "(DFSPH).",
        {bind<SolverAccess>({.key = "method",
                             .label = "Method",
                             .help = "wcsph: weakly compressible, a step limited by the speed of "
                                     "sound (10 × max_speed). dfsph: divergence-free, "
                                     "incompressible to density_error, a step limited only by "
                                     "the flow's speed; its jets splash less and trap less "
                                     "air (docs/VALIDATION.md \"Bubbles with DFSPH\").",
                             .choices = {"wcsph", "dfsph"}},
                            &SolverSettings::method),
         bind<SolverAccess>({.key = "particle_spacing",
                             .label = "Particle spacing",
                             .unit = "m",
                             .minimum = 0.001,
                             .maximum = 1.0,
                             .help = "Initial distance between water particles; halving it "
                                     "gives 8 times as many particles."},
                            &SolverSettings::particleSpacing),
         bind<SolverAccess>({.key = "support_factor",
                             .label = "Support factor",
                             .minimum = 1.5,
                             .maximum = 3.0,
                             .help = "Kernel support radius as a multiple of the particle "
                                     "spacing."},
                            &SolverSettings::supportFactor),
         bind<SolverAccess>({.key = "rest_density",
                             .label = "Rest density",
                             .unit = "kg/m³",
                             .minimum = 100.0,
                             .maximum = 20000.0,
                             .help = "Density of the liquid at rest (water: 1000)."},
                            &SolverSettings::restDensity),
         bind<SolverAccess>({.key = "max_speed",
                             .label = "Maximum speed",
                             .unit = "m/s",
                             .minimum = 0.1,
                             .maximum = 200.0,
                             .help = "Largest speed expected in the flow; the speed of sound is "
                                     "10 times this, which keeps density errors near 1 %."},
                            &SolverSettings::maxSpeed),
         bind<SolverAccess>({.key = "viscosity_alpha",
                             .label = "Viscosity α",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .help = "Monaghan artificial viscosity between water particles."},
                            &SolverSettings::viscosityAlpha),
         bind<SolverAccess>({.key = "wall_viscosity",
                             .label = "Wall viscosity",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .help = "Artificial viscosity against solid walls, i.e. wall "
                                     "friction."},
                            &SolverSettings::wallViscosity),
         bind<SolverAccess>({.key = "wall_restitution",
                             .label = "Wall restitution",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .help = "Share of the normal speed kept when water hits a wall "
                                     "(0 = no bounce)."},
                            &SolverSettings::wallRestitution),
         bind<SolverAccess>({.key = "cfl_factor",
                             .label = "CFL factor",
                             .minimum = 0.05,
                             .maximum = 0.6,
                             .help = "λ in the time step Δt = λ h / (c + |v|max); smaller is "
                                     "steadier and slower."},
                            &SolverSettings::cflFactor),
         bind<SolverAccess>({.key = "shepard_interval",
                             .label = "Shepard interval",
                             .unit = "steps",
                             .minimum = 0,
                             .maximum = 10000,
                             .help = "Steps between Shepard density re-initialisations (0 = "
                                     "never)."},
                            &SolverSettings::shepardInterval),
         bind<SolverAccess>({.key = "max_density_error",
                             .label = "Maximum density error",
                             .minimum = 0.01,
                             .maximum = 10.0,
                             .help = "The bake stops as blown up when |ρ/ρ₀ − 1| exceeds this "
                                     "anywhere."},
                            &SolverSettings::maxDensityError),
         bind<SolverAccess>({.key = "gravity",
                             .label = "Gravity",
                             .unit = "m/s²",
                             .minimum = -100.0,
                             .maximum = 100.0,
                             .help = "Gravitational acceleration; y is up."},
                            &SolverSettings::gravity),
         bind<SolverAccess>({.key = "density_error",
                             .label = "Density error (DFSPH)",
                             .minimum = 1e-6,
                             .maximum = 0.05,
                             .help = "Average compression |ρ/ρ₀ − 1| the density solve iterates "
                                     "down to (0.0001 = 0.01 %)."},
                            &SolverSettings::densityErrorTarget),
         bind<SolverAccess>({.key = "divergence_error",
                             .label = "Divergence error (DFSPH)",
                             .minimum = 1e-5,
                             .maximum = 0.1,
                             .help = "Average compression rate Δt·(Dρ/Dt)/ρ₀ the divergence "
                                     "solve iterates down to (0.001 = 0.1 %)."},
                            &SolverSettings::divergenceErrorTarget),
         bind<SolverAccess>({.key = "min_iterations",
                             .label = "Minimum iterations (DFSPH)",
                             .minimum = 0,
                             .maximum = 100,
                             .help = "Iterations each solve takes even when already converged."},
                            &SolverSettings::minIterations),
         bind<SolverAccess>({.key = "max_iterations",
                             .label = "Maximum iterations (DFSPH)",
                             .minimum = 1,
                             .maximum = 10000,
                             .help = "Iterations after which a solve gives up for the step; the "
                                     "bake stops when that happens many steps in a row."},
                            &SolverSettings::maxIterations),
         bind<SolverAccess>({.key = "flow_cfl_factor",
                             .label = "Flow CFL factor (DFSPH)",
                             .minimum = 0.05,
                             .maximum = 1.0,
                             .help = "λ in the time step Δt = λ Δx / |v|max: the fastest "
                                     "particle moves λ spacings per step."},
                            &SolverSettings::flowCflFactor),
         bind<SolverAccess>({.key = "xsph",
                             .label = "XSPH viscosity (DFSPH)",
                             .minimum = 0.0,
                             .maximum = 0.5,
                             .help = "Each step moves a particle's velocity this share toward "
                                     "its neighbours' kernel-weighted mean (Monaghan's XSPH): "
                                     "the viscosity, stable at any step."},
                            &SolverSettings::xsphFactor),
         bind<SolverAccess>({.key = "wall_xsph",
                             .label = "Wall XSPH (DFSPH)",
                             .minimum = 0.0,
                             .maximum = 1.0,
                             .help = "The same toward the velocity of the walls and bodies the "
                                     "water touches: wall friction (0 = free slip)."},
                            &SolverSettings::wallXsphFactor),
         bind<SolverAccess>({.key = "min_time_step",
                             .label = "Minimum time step (DFSPH)",
                             .unit = "s",
                             .minimum = 1e-6,
                             .maximum = 0.1,
                             .help = "The step never gets shorter than this (except to land on "
                                     "a frame); a flow that would need less is reported."},
                            &SolverSettings::minTimeStep),
         bind<SolverAccess>({.key = "max_time_step",
                             .label = "Maximum time step (DFSPH)",
                             .unit = "s",
                             .minimum = 1e-5,
                             .maximum = 0.1,
                             .help = "The step never gets longer than this, however slow the "
                                     "flow."},
                            &SolverSettings::maxTimeStep)});
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
                             .help = "Frames per second of simulated time."},
                            &FrameSettings::fps),
         bind<FramesAccess>({.key = "end_frame",
                             .label = "End frame",
                             .minimum = 2,
                             .maximum = 100000,
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
                                .help = "Inside corner with the smallest x, y and z (the floor)."},
                               &ContainerSettings::min),
         bind<ContainerAccess>({.key = "max",
                                .label = "Maximum corner",
                                .unit = "m",
                                .minimum = -kMaxCoordinate,
                                .maximum = kMaxCoordinate,
                                .help = "Inside corner with the largest x, y and z (y is the "
                                        "rim)."},
                               &ContainerSettings::max),
         bind<ContainerAccess>({.key = "headroom",
                                .label = "Headroom",
                                .unit = "m",
                                .minimum = 0.0,
                                .maximum = 100.0,
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
                                 .help = "Shown in the scene tree and in messages."},
                                &FluidBlock::name),
         bind<FluidBlockAccess>({.key = "min",
                                 .label = "Minimum corner",
                                 .unit = "m",
                                 .minimum = -kMaxCoordinate,
                                 .maximum = kMaxCoordinate,
                                 .help = "Corner with the smallest x, y and z."},
                                &FluidBlock::min),
         bind<FluidBlockAccess>({.key = "max",
                                 .label = "Maximum corner",
                                 .unit = "m",
                                 .minimum = -kMaxCoordinate,
                                 .maximum = kMaxCoordinate,
                                 .help = "Corner with the largest x, y and z."},
                                &FluidBlock::max),
         bind<FluidBlockAccess>({.key = "initial_velocity",
                                 .label = "Initial velocity",
                                 .unit = "m/s",
                                 .minimum = -100.0,
                                 .maximum = 100.0,
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
                               .help = "Shown in the scene tree and in messages."},
                              &BoxObstacle::name),
         obstacleShape(),
         bind<ObstacleAccess>({.key = "center",
                               .label = "Centre",
                               .unit = "m",
                               .minimum = -kMaxCoordinate,
                               .maximum = kMaxCoordinate,
                               .help = "Centre of the box."},
                              &BoxObstacle::center),
         bind<ObstacleAccess>({.key = "size",
                               .label = "Size",
                               .unit = "m",
                               .minimum = 0.0,
                               .maximum = kMaxCoordinate,
                               .minimumExclusive = true,
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
                              .help = "Shown in the scene tree and in messages."},
                             &InflowEmitterSettings::name),
         bind<EmitterAccess>({.key = "shape",
                              .label = "Shape",
                              .help = "Nozzle cross-section: a disc (radius) or a rectangle "
                                      "(width × height).",
                              .choices = {"disc", "rectangle"}},
                             &InflowEmitterSettings::shape),
         bind<EmitterAccess>({.key = "position",
                              .label = "Position",
                              .unit = "m",
                              .minimum = -kMaxCoordinate,
                              .maximum = kMaxCoordinate,
                              .help = "Centre of the nozzle's exit plane."},
                             &InflowEmitterSettings::position),
         bind<EmitterAccess>({.key = "direction",
                              .label = "Direction",
                              .minimum = -1000.0,
                              .maximum = 1000.0,
                              .help = "Direction of the jet; any length but zero."},
                             &InflowEmitterSettings::direction),
         bind<EmitterAccess>({.key = "radius",
                              .label = "Radius",
                              .unit = "m",
                              .minimum = 0.0,
                              .maximum = 100.0,
                              .minimumExclusive = true,
                              .help = "Radius of a disc nozzle.",
                              .appliesWhenKey = "shape",
                              .appliesWhenValues = {"disc"}},
                             &InflowEmitterSettings::radius),
         bind<EmitterAccess>({.key = "width",
                              .label = "Width",
                              .unit = "m",
                              .minimum = 0.0,
                              .maximum = 100.0,
                              .minimumExclusive = true,
                              .help = "Side of a rectangular nozzle along the horizontal "
                                      "perpendicular of the direction (x for a vertical jet).",
                              .appliesWhenKey = "shape",
                              .appliesWhenValues = {"rectangle"}},
                             &InflowEmitterSettings::width),
         bind<EmitterAccess>({.key = "height",
                              .label = "Height",
                              .unit = "m",
                              .minimum = 0.0,
                              .maximum = 100.0,
                              .minimumExclusive = true,
                              .help = "Side of a rectangular nozzle along the other "
                                      "perpendicular (z for a vertical jet).",
                              .appliesWhenKey = "shape",
                              .appliesWhenValues = {"rectangle"}},
                             &InflowEmitterSettings::height),
         bind<EmitterAccess>({.key = "speed",
                              .label = "Speed",
                              .unit = "m/s",
                              .minimum = 0.0,
                              .maximum = 200.0,
                              .minimumExclusive = true,
                              .help = "Speed of the emitted water; at most solver.max_speed."},
                             &InflowEmitterSettings::speed),
         bind<EmitterAccess>({.key = "start_time",
                              .label = "Start time",
                              .unit = "s",
                              .minimum = 0.0,
                              .maximum = 100000.0,
                              .help = "Simulated time of the first layer."},
                             &InflowEmitterSettings::startTime),
         bind<EmitterAccess>({.key = "stop_time",
                              .label = "Stop time",
                              .unit = "s",
                              .minimum = 0.0,
                              .maximum = 100000.0,
                              .help = "Nothing is emitted from this simulated time on."},
                             &InflowEmitterSettings::stopTime),
         bind<EmitterAccess>({.key = "max_particles",
                              .label = "Particle budget",
                              .minimum = 1,
                              .maximum = 20000000,
                              .help = "Most particles this emitter creates; it stops at the last "
                                      "whole layer that fits."},
                             &InflowEmitterSettings::maxParticles)});
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
    sections.push_back(bubblesSection());
    sections.push_back(surfaceMeshSection());
    sections.push_back(bubbleMeshSection());
    sections.push_back(subgridBubblesSection());
    return sections;
}

} // namespace airtrap
