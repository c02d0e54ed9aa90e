#include "scene/SceneValidator.h"

#include "core/Error.h"
#include "scene/InflowNozzle.h"
#include "scene/ParameterCodec.h"
#include "scene/SceneSchema.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace airtrap {
namespace {

//! Coordinates closer than this count as equal: values typed as decimals are not exact.
constexpr double kTolerance = 1e-9;
constexpr const char* kAxes[] = {"x", "y", "z"};

std::string number(double value) {
    return ParameterCodec::formatNumber(value);
}

//! A parameter's dotted key for messages, from its declaration ("solver.max_speed").
template <class Owner, class Field>
std::string key(Field Owner::*member) {
    return SceneSchema::keyOf(member);
}

//! A parameter's own key, for messages that name its element first ("stop_time").
template <class Owner, class Field>
const std::string& name(Field Owner::*member) {
    return SceneSchema::nameOf(member);
}

//! Overlaps listed one by one; the rest are counted in one line.
constexpr std::size_t kListedOverlaps = 10;

std::string blockLabel(const char* section, std::size_t index, const std::string& name) {
    return std::string(section) + "[" + std::to_string(index) + "] (" +
           ParameterCodec::formatValue(name) + ")";
}

Aabb obstacleBox(const BoxObstacle& obstacle) {
    return {obstacle.center - 0.5 * obstacle.size, obstacle.center + 0.5 * obstacle.size};
}

bool overlap(const Aabb& a, const Aabb& b) {
    for (int axis = 0; axis < 3; ++axis)
        if (std::max(a.min[axis], b.min[axis]) >= std::min(a.max[axis], b.max[axis]) - kTolerance)
            return false;
    return true;
}

class Checker {
public:
    explicit Checker(const Scene& scene)
        : scene_(scene), source_(scene.sourcePath.empty() ? "scene" : scene.sourcePath) {}

    SceneIssues run() {
        checkFields();
        // Cross-field rules assume fields in range; with bad fields they would only add noise.
        if (!issues_.ok())
            return issues_;
        // Inside an inverted container nothing fits; saying so for every block is noise.
        const bool containerValid = checkContainer();
        checkFluidBlocks(containerValid);
        if (containerValid)
            checkObstacles();
        checkEmitters(containerValid);
        checkParticleCount();
        checkOverlaps();
        checkBodySizes();
        checkBodyNames();
        checkKeyframes();
        checkBubbles();
        checkStartingSpeeds();
        checkPressureSolve();
        checkSurfaceMesh();
        checkSubgridBubbles();
        return issues_;
    }

private:
    void error(const std::string& message) { issues_.errors.push_back(source_ + ": " + message); }
    void warning(const std::string& message) {
        issues_.warnings.push_back(source_ + ": " + message);
    }

    void checkFields() {
        for (const SchemaSection& section : SceneSchema::sections())
            for (std::size_t element = 0; element < section.elementCount(scene_); ++element)
                for (const BoundParameter& parameter : section.parameters) {
                    const std::string path =
                        SceneSchema::pathOf(section, element, parameter.declaration.key);
                    const std::string problem = ParameterCodec::check(
                        parameter.declaration, parameter.get(scene_, element), path);
                    if (!problem.empty())
                        error(problem);
                }
    }

    bool checkContainer() {
        const ContainerSettings& container = scene_.container;
        bool valid = true;
        for (int axis = 0; axis < 3; ++axis)
            if (container.min[axis] >= container.max[axis]) {
                error(key(&ContainerSettings::min) + "." + kAxes[axis] + " = " +
                      number(container.min[axis]) + " must be less than " +
                      key(&ContainerSettings::max) + "." + kAxes[axis] + " = " +
                      number(container.max[axis]));
                valid = false;
            }
        return valid;
    }

    //! Reports where `box` sticks out of `bounds`, one message per face.
    void checkInside(const std::string& label, const Aabb& box, const Aabb& bounds,
                     const std::string& boundsName) {
        for (int axis = 0; axis < 3; ++axis) {
            const std::string a = kAxes[axis];
            if (box.min[axis] < bounds.min[axis] - kTolerance)
                error(label + " reaches outside the " + boundsName + ": min." + a + " = " +
                      number(box.min[axis]) + " < " + number(bounds.min[axis]));
            if (box.max[axis] > bounds.max[axis] + kTolerance)
                error(label + " reaches outside the " + boundsName + ": max." + a + " = " +
                      number(box.max[axis]) + " > " + number(bounds.max[axis]));
        }
    }

    void checkFluidBlocks(bool containerValid) {
        if (scene_.fluidBlocks.empty() && scene_.emitters.empty())
            error("fluid_blocks is empty and there are no emitters; a scene needs water: at "
                  "least one fluid block or emitter");
        const double spacing = scene_.solver.particleSpacing;
        for (std::size_t i = 0; i < scene_.fluidBlocks.size(); ++i) {
            const FluidBlock& block = scene_.fluidBlocks[i];
            const std::string label = blockLabel("fluid_blocks", i, block.name);
            for (int axis = 0; axis < 3; ++axis) {
                const std::string a = kAxes[axis];
                if (block.min[axis] >= block.max[axis])
                    error(label + ": " + name(&FluidBlock::min) + "." + a + " = " +
                          number(block.min[axis]) + " must be less than " + name(&FluidBlock::max) +
                          "." + a + " = " + number(block.max[axis]));
                else if (block.max[axis] - block.min[axis] < spacing)
                    warning(label + " is thinner than " + key(&SolverSettings::particleSpacing) +
                            " = " + number(spacing) + " m along " + a +
                            "; it may hold no particles");
                else
                    checkBlockFit(label, block, axis, spacing);
            }
            // The domain, not just the tank: water may start above the rim and fall in.
            if (containerValid)
                checkInside(label, {block.min, block.max}, scene_.domain(),
                            "domain (container plus headroom)");
        }
    }

    //! The water is a lattice of whole spacings: a block whose extent is not a whole number of
    //! them holds a little more or less water than drawn (a 0.55 m pool at 0.02 m is filled
    //! 28 layers deep, 0.56 m), which the artist should hear of rather than find in the level.
    void checkBlockFit(const std::string& label, const FluidBlock& block, int axis,
                       double spacing) {
        const double extent = block.max[axis] - block.min[axis];
        const double wall = scene_.domain().max[axis];
        const int layers = block.layers(axis, spacing, wall);
        const double filled = layers * spacing;
        if (std::abs(filled - extent) <= 1e-6 * spacing)
            return;
        const bool heldByWall = layers < std::lround(extent / spacing);
        // Lengths to a micrometre: 28 × 0.02 is 0.56000000000000005 in binary.
        char text[320];
        std::snprintf(text, sizeof text,
                      " is %.6g m along %s, not a whole number of %s = %s m: it is filled with %d "
                      "layers, %.6g m of water%s (max.%s = %.6g would draw exactly that)",
                      extent, kAxes[axis], key(&SolverSettings::particleSpacing).c_str(),
                      number(spacing).c_str(), layers, filled,
                      heldByWall ? ", as many as fit inside the container" : "", kAxes[axis],
                      block.min[axis] + filled);
        warning(label + text);
    }

    void checkObstacles() {
        for (std::size_t i = 0; i < scene_.obstacles.size(); ++i)
            checkInside(blockLabel("obstacles", i, scene_.obstacles[i].name),
                        obstacleBox(scene_.obstacles[i]), scene_.domain(),
                        "domain (container plus headroom)");
    }

    void checkEmitters(bool containerValid) {
        const SolverSettings& solver = scene_.solver;
        for (std::size_t i = 0; i < scene_.emitters.size(); ++i) {
            const InflowEmitterSettings& emitter = scene_.emitters[i];
            const std::string label = blockLabel("emitters", i, emitter.name);
            if (emitter.stopTime <= emitter.startTime)
                error(label + ": " + name(&InflowEmitterSettings::stopTime) + " = " +
                      number(emitter.stopTime) + " s must be later than " +
                      name(&InflowEmitterSettings::startTime) + " = " + number(emitter.startTime) +
                      " s");
            if (emitter.speed > solver.maxSpeed + kTolerance)
                error(label + ": " + name(&InflowEmitterSettings::speed) + " = " +
                      number(emitter.speed) + " m/s exceeds " + key(&SolverSettings::maxSpeed) +
                      " = " + number(solver.maxSpeed) + " m/s; the speed of sound (10 × " +
                      name(&SolverSettings::maxSpeed) + ") would be too slow for the jet. Raise " +
                      key(&SolverSettings::maxSpeed) + " or lower the speed");
            if (emitter.direction.norm() < kTolerance) {
                error(label + ": " + name(&InflowEmitterSettings::direction) +
                      " is zero; give the jet a direction, e.g. [0, -1, 0]");
                continue;
            }
            if (containerValid) {
                const Vec3d half = InflowNozzle::exitHalfExtent(emitter);
                checkInside(label + "'s nozzle", {emitter.position - half, emitter.position + half},
                            scene_.domain(), "domain (container plus headroom)");
            }
            const InflowNozzle nozzle(emitter, solver.particleSpacing);
            if (nozzle.layerBudget() == 0)
                warning(label + ": " + name(&InflowEmitterSettings::maxParticles) + " = " +
                        std::to_string(emitter.maxParticles) + " is less than one layer of " +
                        std::to_string(nozzle.particlesPerLayer()) +
                        " particles; it emits nothing");
        }
    }

    void checkParticleCount() {
        const double spacing = scene_.solver.particleSpacing;
        double volume = 0.0;
        for (const FluidBlock& block : scene_.fluidBlocks)
            volume += (block.max - block.min).cwiseMax(0.0).prod();
        double budgets = 0.0;
        for (const InflowEmitterSettings& emitter : scene_.emitters)
            budgets += emitter.maxParticles;
        const double particles = volume / (spacing * spacing * spacing) + budgets;
        if (particles <= SceneValidator::kMaxParticles)
            return;
        char text[320];
        std::snprintf(text, sizeof text,
                      "the fluid blocks%s hold about %.1f million particles at %s = %s m; the "
                      "limit is %.0f million. %s",
                      budgets > 0.0 ? " and emitter budgets" : "", particles / 1e6,
                      key(&SolverSettings::particleSpacing).c_str(), number(spacing).c_str(),
                      SceneValidator::kMaxParticles / 1e6,
                      particleCountAdvice(volume, budgets).c_str());
        error(text);
    }

    //! What brings the count within the limit: a coarser spacing when an allowed one does,
    //! else smaller blocks or budgets.
    std::string particleCountAdvice(double volume, double budgets) const {
        const double room = SceneValidator::kMaxParticles - budgets;
        if (room <= 0.0)
            return "The emitters' particle budgets alone exceed it: lower their " +
                   SceneSchema::nameOf(&InflowEmitterSettings::maxParticles) + ".";
        const double coarsest =
            SceneSchema::declarationOf(&SolverSettings::particleSpacing).maximum;
        // Just above the spacing that fills the room exactly, so that it fits after rounding.
        const double needed = std::cbrt(volume / room) * 1.005;
        char text[160];
        if (needed > coarsest)
            std::snprintf(text, sizeof text,
                          "Even the coarsest spacing allowed (%s m) gives too many: make the fluid "
                          "blocks smaller.",
                          number(coarsest).c_str());
        else
            std::snprintf(text, sizeof text,
                          "Use a spacing of at least %.2g m or smaller fluid blocks.", needed);
        return text;
    }

    void checkOverlaps() {
        const auto& blocks = scene_.fluidBlocks;
        // One line per pair, but not millions of them: a scene of 3 001 touching blocks printed
        // 4.5 million lines.
        std::size_t pairs = 0;
        const auto report = [&](std::string text) {
            if (++pairs <= kListedOverlaps)
                warning(std::move(text));
        };
        for (std::size_t i = 0; i < blocks.size(); ++i) {
            const Aabb box{blocks[i].min, blocks[i].max};
            const std::string label = blockLabel("fluid_blocks", i, blocks[i].name);
            for (std::size_t j = i + 1; j < blocks.size(); ++j)
                if (overlap(box, {blocks[j].min, blocks[j].max}))
                    report(label + " overlaps " + blockLabel("fluid_blocks", j, blocks[j].name) +
                           "; the overlap holds the first block's water only, and the two "
                           "particle lattices meet unevenly at its edge");
            for (std::size_t j = 0; j < scene_.obstacles.size(); ++j)
                if (overlap(box, obstacleBox(scene_.obstacles[j])))
                    report(label + " overlaps " +
                           blockLabel("obstacles", j, scene_.obstacles[j].name) +
                           "; the water in the overlap starts inside a solid");
        }
        if (pairs > kListedOverlaps)
            warning("and " + std::to_string(pairs - kListedOverlaps) +
                    " more overlapping pairs of fluid blocks and obstacles, not listed");
    }

    void checkBodySizes() {
        const double spacing = scene_.solver.particleSpacing;
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i) {
            const RigidBodySettings& body = scene_.bodies[i];
            const std::string label = blockLabel("bodies", i, body.name);
            const auto tooSmall = [&](const std::string& field, double value) {
                if (value < spacing - kTolerance)
                    error(label + "." + field + " = " + number(value) + " m is less than " +
                          key(&SolverSettings::particleSpacing) + " = " + number(spacing) +
                          " m; the water cannot feel a smaller solid");
            };
            checkBodyFitsTheDomain(label, body);
            if (body.shape == "box")
                tooSmall(name(&RigidBodySettings::size), body.size.minCoeff());
            if (body.shape == "sphere" || body.shape == "cylinder")
                tooSmall(name(&RigidBodySettings::radius), body.radius);
            if (body.shape == "cylinder")
                tooSmall(name(&RigidBodySettings::height), body.height);
            if (body.shape == "mesh" && body.mesh.empty())
                error(label + "." + name(&RigidBodySettings::mesh) +
                      " is empty; shape \"mesh\" needs a mesh file");
        }
    }

    //! Sampling a body's surface and checking its placement cost time as its size over the
    //! spacing, squared and cubed: a sphere of 5 m in a 1-m tank kept validation busy for
    //! seconds. A body wider than the domain's diagonal fits nowhere in it, whatever its pose,
    //! so it is refused before that work. (Mesh bodies are measured once their file is read:
    //! BodyBuilder::checkFitsTheDomain.)
    void checkBodyFitsTheDomain(const std::string& label, const RigidBodySettings& body) {
        double across = 0.0;
        std::string field;
        if (body.shape == "box") {
            across = body.size.norm();
            field = name(&RigidBodySettings::size);
        } else if (body.shape == "sphere") {
            across = 2.0 * body.radius;
            field = name(&RigidBodySettings::radius);
        } else if (body.shape == "cylinder") {
            across = std::hypot(2.0 * body.radius, body.height);
            field = name(&RigidBodySettings::radius) + " and " + name(&RigidBodySettings::height);
        } else {
            return;
        }
        const double diagonal = scene_.domain().size().norm();
        if (across > diagonal)
            error(label + "." + field + ": the " + body.shape + " is " + number(across) +
                  " m across, larger than the domain (container plus headroom, " +
                  number(diagonal) + " m corner to corner); expected a body that fits inside");
    }

    void checkBubbles() {
        const BubbleSettings& bubbles = scene_.bubbles;
        // Paper §3.3.2: ε₁ < ε₂ ≤ 0; equal values (−1 for no interaction at all) are allowed.
        if (bubbles.approachRestitution > bubbles.overlapRestitution)
            error(key(&BubbleSettings::approachRestitution) + " = " +
                  number(bubbles.approachRestitution) + " exceeds " +
                  key(&BubbleSettings::overlapRestitution) + " = " +
                  number(bubbles.overlapRestitution) +
                  "; approaching bubbles take at most the overlapping ones' restitution "
                  "(ε₁ ≤ ε₂ ≤ 0)");
        // With DFSPH max_speed sets nothing the bubbles depend on (it is WCSPH's speed of
        // sound's basis).
        if (bubbles.enabled && !scene_.solver.divergenceFree() &&
            bubbles.maxRiseSpeed > scene_.solver.maxSpeed)
            error(key(&BubbleSettings::maxRiseSpeed) + " = " + number(bubbles.maxRiseSpeed) +
                  " m/s exceeds " + key(&SolverSettings::maxSpeed) + " = " +
                  number(scene_.solver.maxSpeed) + " m/s; raise " + key(&SolverSettings::maxSpeed) +
                  " or lower the cap");
    }

    //! WCSPH's speed of sound is 10 × max_speed: water that starts faster than max_speed
    //! compresses beyond what that sound speed holds and the bake stops in its first frames.
    void checkStartingSpeeds() {
        if (scene_.solver.divergenceFree())
            return;
        const double limit = scene_.solver.maxSpeed;
        const auto tooFast = [&](const std::string& what, double speed) {
            error(what + " is " + number(speed) + " m/s, above " + key(&SolverSettings::maxSpeed) +
                  " = " + number(limit) + " m/s, the basis of the speed of sound (WCSPH): raise " +
                  key(&SolverSettings::maxSpeed) + " to at least " + number(speed));
        };
        for (std::size_t i = 0; i < scene_.fluidBlocks.size(); ++i) {
            const FluidBlock& block = scene_.fluidBlocks[i];
            if (const double speed = block.initialVelocity.norm(); speed > limit)
                tooFast(blockLabel("fluid_blocks", i, block.name) + "." +
                            name(&FluidBlock::initialVelocity) + "'s speed",
                        speed);
        }
        for (std::size_t i = 0; i < scene_.emitters.size(); ++i) {
            const InflowEmitterSettings& emitter = scene_.emitters[i];
            if (emitter.speed > limit)
                tooFast(blockLabel("emitters", i, emitter.name) + "." +
                            name(&InflowEmitterSettings::speed),
                        emitter.speed);
        }
    }

    void checkPressureSolve() {
        const SolverSettings& solver = scene_.solver;
        if (solver.minIterations > solver.maxIterations)
            error(key(&SolverSettings::minIterations) + " = " +
                  std::to_string(solver.minIterations) + " exceeds " +
                  key(&SolverSettings::maxIterations) + " = " +
                  std::to_string(solver.maxIterations));
        if (solver.minTimeStep > solver.maxTimeStep)
            error(key(&SolverSettings::minTimeStep) + " = " + number(solver.minTimeStep) +
                  " s exceeds " + key(&SolverSettings::maxTimeStep) + " = " +
                  number(solver.maxTimeStep) + " s");
    }

    void checkSurfaceMesh() {
        if (const std::string problem = SceneValidator::surfaceMeshRule(scene_.surfaceMesh);
            !problem.empty())
            error(problem);
    }

    void checkSubgridBubbles() {
        const SubgridBubbleSettings& subgrid = scene_.subgridBubbles;
        if (subgrid.minSize > subgrid.maxSize)
            error(key(&SubgridBubbleSettings::minSize) + " = " + number(subgrid.minSize) +
                  " exceeds " + key(&SubgridBubbleSettings::maxSize) + " = " +
                  number(subgrid.maxSize) + "; the radii are drawn between the two");
    }

    void checkBodyNames() {
        for (std::size_t i = 0; i < scene_.bodies.size(); ++i)
            for (std::size_t j = 0; j < i; ++j)
                if (scene_.bodies[i].name == scene_.bodies[j].name)
                    error(blockLabel("bodies", i, scene_.bodies[i].name) + " has the name of " +
                          blockLabel("bodies", j, scene_.bodies[j].name) +
                          "; keyframes find bodies by name, so names must differ");
    }

    const RigidBodySettings* bodyNamed(const std::string& name) const {
        for (const RigidBodySettings& body : scene_.bodies)
            if (body.name == name)
                return &body;
        return nullptr;
    }

    void checkKeyframes() {
        for (std::size_t i = 0; i < scene_.keyframes.size(); ++i) {
            const BodyKeyframe& key = scene_.keyframes[i];
            const std::string bodyKey = SceneSchema::keyOf(&BodyKeyframe::body, i);
            const RigidBodySettings* body = bodyNamed(key.body);
            if (!body) {
                error(bodyKey + " = " + ParameterCodec::formatValue(key.body) +
                      " names no body; expected the name of a kinematic body");
                continue;
            }
            if (body->motion != "kinematic")
                error(bodyKey + " = " + ParameterCodec::formatValue(key.body) + " is " +
                      body->motion + "; keyframes move kinematic bodies only");
            for (std::size_t j = 0; j < i; ++j)
                if (scene_.keyframes[j].body == key.body &&
                    std::abs(scene_.keyframes[j].time - key.time) < kTolerance)
                    error(SceneSchema::keyOf(&BodyKeyframe::time, i) + " = " + number(key.time) +
                          " s repeats keyframes[" + std::to_string(j) +
                          "] of the same body; times must differ");
        }
    }

    const Scene& scene_;
    std::string source_;
    SceneIssues issues_;
};

} // namespace

std::string SceneValidator::surfaceMeshRule(const SurfaceMeshSettings& surface) {
    // OpenVDB leaves out spheres narrower than 1.5 voxels: the water would have holes.
    constexpr double kMinRadiusInVoxels = 1.5;
    if (surface.particleRadius >= kMinRadiusInVoxels * surface.voxelSize)
        return {};
    return key(&SurfaceMeshSettings::particleRadius) + " = " + number(surface.particleRadius) +
           " is less than " + number(kMinRadiusInVoxels) + " × " +
           key(&SurfaceMeshSettings::voxelSize) + " = " +
           number(kMinRadiusInVoxels * surface.voxelSize) + "; particles narrower than " +
           number(kMinRadiusInVoxels) + " voxels would leave holes in the water mesh";
}

SceneIssues SceneValidator::check(const Scene& scene) {
    return Checker(scene).run();
}

std::vector<std::string> SceneValidator::ruleDescriptions() {
    return {
        "Every value lies in its declared range (the tables above).",
        "`container.min` is below `container.max` on every axis.",
        "There is water: at least one fluid block or emitter. Each fluid block has `min` below "
        "`max` on every axis and lies inside the domain: the container plus `headroom` above its "
        "rim.",
        "Every obstacle lies inside the domain: the container plus `headroom` above its rim.",
        "Every emitter has a non-zero `direction`, `stop_time` later than `start_time`, `speed` "
        "at most `solver.max_speed` (the speed of sound is 10 × `max_speed`), and its nozzle "
        "(the disc or rectangle across the direction) lies inside the domain.",
        "The fluid blocks and the emitters' `max_particles` together hold at most " +
            number(kMaxParticles / 1e6) +
            " million particles (the blocks' total volume / `particle_spacing`³ plus the "
            "budgets).",
        "Bodies have different names; boxes, spheres and cylinders are at least "
        "`particle_spacing` in every size; a mesh body names a closed, readable mesh file "
        "(relative to the scene file; a regular file, not a folder, FIFO or device); every body, "
        "a mesh scaled by `mesh_scale`, is no wider than the domain's diagonal (checked before "
        "the body is sampled); every body lies inside the domain.",
        "Every keyframe names a kinematic body, and no two keyframes of a body share a time.",
        "`bubbles.approach_restitution` is at most `bubbles.overlap_restitution` (ε₁ ≤ ε₂ ≤ 0); "
        "with bubbles enabled and WCSPH, `bubbles.max_rise_speed` is at most `solver.max_speed`.",
        "With WCSPH, no fluid block starts faster than `solver.max_speed` and no emitter emits "
        "faster (the speed of sound is 10 × `solver.max_speed`).",
        "`surface_mesh.particle_radius` is at least 1.5 × `surface_mesh.voxel_size`.",
        "`subgrid_bubbles.min_size` is at most `subgrid_bubbles.max_size`.",
        "Warnings, which do not stop a bake: fluid blocks that overlap each other or an "
        "obstacle, fluid blocks thinner than `particle_spacing`, fluid blocks whose size is not "
        "a whole number of `particle_spacing` (the message says how deep the water is filled), "
        "emitters whose "
        "`max_particles` is less than one layer of their nozzle, and bodies that overlap an "
        "obstacle, the container or each other at t = 0 (contacts would push them apart with a "
        "jolt).",
        "Notes, printed as `note:` and never asked about: a body that starts in a fluid block. "
        "Placing a body in the water is how a scene floats or sinks one "
        "(`samples/buoyancy.json`): the body displaces the water, and the block's particles "
        "inside it are left out.",
    };
}

} // namespace airtrap
