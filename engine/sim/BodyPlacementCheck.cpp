#include "sim/BodyPlacementCheck.h"

#include "core/Error.h"
#include "scene/ParameterCodec.h"
#include "sim/SceneSetup.h"

#include <cmath>

namespace airtrap {
namespace {

//! Overlaps shallower than this share of a spacing are contact, not overlap.
constexpr double kOverlapTolerance = 0.25;
//! m; the boundary particles the surface is found from are single precision.
constexpr double kDomainTolerance = 1e-6;

std::string label(const Scene& scene, std::size_t index) {
    return "bodies[" + std::to_string(index) + "] (" +
           ParameterCodec::formatValue(scene.bodies[index].name) + ")";
}

std::string sceneryLabel(const Scene& scene, std::size_t index) {
    if (index == 0)
        return "the container";
    return "obstacles[" + std::to_string(index - 1) + "] (" +
           ParameterCodec::formatValue(scene.obstacles[index - 1].name) + ")";
}

//! To the micrometre: the surface points carry single-precision noise.
std::string rounded(double metres) {
    return ParameterCodec::formatNumber(std::round(metres * 1e6) / 1e6);
}

//! Box around the solid's surface points of `body`.
Aabb surfaceBounds(const RigidBody& body) {
    Aabb box{Vec3d::Constant(1e300), Vec3d::Constant(-1e300)};
    for (std::size_t k = 0; k < body.boundary().size(); ++k) {
        const Vec3d x = body.surfacePoint(k);
        box.min = box.min.cwiseMin(x);
        box.max = box.max.cwiseMax(x);
    }
    return box;
}

//! Whether any surface point of `a` lies deeper than `depth` inside `b`.
bool penetrates(const RigidBody& a, const RigidBody& b, double depth) {
    for (std::size_t k = 0; k < a.boundary().size(); ++k)
        if (b.signedDistance(a.surfacePoint(k)) < -depth)
            return true;
    return false;
}

void checkDomain(const Scene& scene, const RigidBody& body, std::size_t index,
                 BodyPlacementCheck::Findings& findings) {
    const Aabb domain = scene.domain();
    const Aabb box = surfaceBounds(body);
    const char* axes[] = {"x", "y", "z"};
    for (int axis = 0; axis < 3; ++axis)
        if (box.min[axis] < domain.min[axis] - kDomainTolerance ||
            box.max[axis] > domain.max[axis] + kDomainTolerance) {
            findings.errors.push_back(label(scene, index) +
                                      " reaches outside the domain (container plus headroom) "
                                      "along " +
                                      axes[axis] + ": it spans " + rounded(box.min[axis]) + " to " +
                                      rounded(box.max[axis]) + " m, the domain " +
                                      ParameterCodec::formatNumber(domain.min[axis]) + " to " +
                                      ParameterCodec::formatNumber(domain.max[axis]) + " m");
            return;
        }
}

//! Whether water of `block` would start inside `body`: a point of the body's surface lies in
//! the block, or the block's centre lies in the body (a block wholly inside it).
bool overlapsWater(const RigidBody& body, const FluidBlock& block, double tolerance) {
    const Aabb inner = Aabb{block.min, block.max}.expanded(-tolerance);
    for (std::size_t k = 0; k < body.boundary().size(); ++k)
        if (inner.contains(body.surfacePoint(k)))
            return true;
    return body.signedDistance(0.5 * (block.min + block.max)) < 0.0;
}

void checkWater(const Scene& scene, const RigidBody& body, std::size_t index,
                BodyPlacementCheck::Findings& findings) {
    const double tolerance = kOverlapTolerance * scene.solver.particleSpacing;
    for (std::size_t f = 0; f < scene.fluidBlocks.size(); ++f) {
        const FluidBlock& block = scene.fluidBlocks[f];
        if (!overlapsWater(body, block, tolerance))
            continue;
        // Placing a body in a block is how a scene floats or sinks one (samples/buoyancy.json):
        // a note, not a warning the editor would ask about before every bake.
        findings.notes.push_back(label(scene, index) + " starts in fluid_blocks[" +
                                 std::to_string(f) + "] (" +
                                 ParameterCodec::formatValue(block.name) +
                                 "); the body displaces it: the block's particles inside the "
                                 "body are left out");
    }
}

void checkBodies(const Scene& scene, const std::vector<RigidBody>& bodies,
                 BodyPlacementCheck::Findings& findings) {
    const std::size_t scenery = SceneSetup::sceneryCount(scene);
    const double depth = kOverlapTolerance * scene.solver.particleSpacing;
    for (std::size_t a = scenery; a < bodies.size(); ++a) {
        const std::size_t index = a - scenery;
        checkDomain(scene, bodies[a], index, findings);
        checkWater(scene, bodies[a], index, findings);
        for (std::size_t b = 0; b < a; ++b) {
            if (!penetrates(bodies[a], bodies[b], depth) &&
                !penetrates(bodies[b], bodies[a], depth))
                continue;
            const std::string other =
                b < scenery ? sceneryLabel(scene, b) : label(scene, b - scenery);
            findings.warnings.push_back(label(scene, index) + " overlaps " + other +
                                        " at t = 0; contacts will push them apart with a jolt");
        }
    }
}

} // namespace

BodyPlacementCheck::Findings BodyPlacementCheck::run(const Scene& scene) {
    Findings findings;
    if (scene.bodies.empty())
        return findings;
    std::vector<RigidBody> bodies;
    try {
        bodies = SceneSetup::buildBodies(scene);
    } catch (const Error& error) {
        findings.errors.push_back(error.what());
        return findings;
    }
    checkBodies(scene, bodies, findings);
    return findings;
}

} // namespace airtrap
