#include "sim/SceneSetup.h"

#include "rigid/BoundarySampler.h"
#include "sim/BodyBuilder.h"
#include "sph/BoundaryVolumes.h"
#include "sph/TaitEquationOfState.h"

#include <cmath>
#include <limits>

namespace airtrap {

namespace {

Aabb obstacleBox(const BoxObstacle& obstacle) {
    return {obstacle.center - 0.5 * obstacle.size, obstacle.center + 0.5 * obstacle.size};
}

bool insideAnyEarlierBlock(const Scene& scene, std::size_t block, const Vec3d& x) {
    for (std::size_t other = 0; other < block; ++other) {
        const FluidBlock& b = scene.fluidBlocks[other];
        if (Aabb{b.min, b.max}.contains(x))
            return true;
    }
    return false;
}

bool insideAnyObstacle(const Scene& scene, const Vec3d& x, double margin) {
    for (const BoxObstacle& obstacle : scene.obstacles)
        if (obstacleBox(obstacle).expanded(margin).contains(x))
            return true;
    return false;
}

//! A static box body whose frame sits at the box's centre, sampled on the surface of `layer`
//! (the solid `shape`'s surface moved half a spacing into the solid).
RigidBody boxBody(const std::string& name, const Aabb& layer, BodyShape shape, double spacing,
                  BoundarySampler::WaterSide side, bool openTop, const CubicSplineKernel& kernel) {
    const Vec3d half = 0.5 * layer.size();
    BoundaryParticles surface = BoundarySampler::sampleBox({-half, half}, spacing, side, openTop);
    BoundaryVolumes::compute(surface, kernel, spacing);
    RigidBody body(name, std::move(surface), std::move(shape), {layer.center(), Quatd::Identity()});
    body.setSurfaceOffset(0.5 * spacing);
    return body;
}

//! The tank and the obstacles: water slides along them (their friction is the solver's wall
//! viscosity), while for bodies they are neutral, so a body's own restitution and friction
//! decide its contacts with them (ContactMaterial::combine).
void setSceneryMaterials(RigidBody& body, const Scene& scene) {
    const ContactMaterial water{scene.solver.wallRestitution, 0.0};
    const ContactMaterial neutral{0.0, std::numeric_limits<double>::infinity()};
    body.setMaterials(water, neutral);
}

} // namespace

std::vector<RigidBody> SceneSetup::buildBodies(const Scene& scene) {
    const double dx = scene.solver.particleSpacing;
    const CubicSplineKernel kernel(static_cast<float>(scene.supportRadius()));
    std::vector<RigidBody> bodies;
    const Aabb inside{scene.container.min, scene.container.max};
    const Aabb tankLayer = inside.expanded(0.5 * dx);
    const Vec3d tankCentre = tankLayer.center();
    bodies.push_back(boxBody("Container", tankLayer,
                             BodyShape::tank({inside.min - tankCentre, inside.max - tankCentre}),
                             dx, BoundarySampler::WaterSide::Inside, true, kernel));
    for (const BoxObstacle& obstacle : scene.obstacles)
        bodies.push_back(boxBody(obstacle.name, obstacleBox(obstacle).expanded(-0.5 * dx),
                                 BodyShape::box(obstacle.size), dx,
                                 BoundarySampler::WaterSide::Outside, false, kernel));
    for (RigidBody& body : bodies)
        setSceneryMaterials(body, scene);
    const BodyBuilder builder(scene, kernel);
    for (std::size_t index = 0; index < scene.bodies.size(); ++index)
        bodies.push_back(builder.build(index));
    return bodies;
}

std::size_t SceneSetup::sceneryCount(const Scene& scene) {
    return 1 + scene.obstacles.size();
}

std::vector<RigidBodyState> SceneSetup::initialBodyStates(const Scene& scene,
                                                          const std::vector<RigidBody>& bodies) {
    std::vector<RigidBodyState> states;
    for (std::size_t b = sceneryCount(scene); b < bodies.size(); ++b)
        states.push_back(bodies[b].state());
    return states;
}

void SceneSetup::fillFluid(const Scene& scene, const std::vector<RigidBody>& bodies,
                           SimulationState& state) {
    const TaitEquationOfState equationOfState(scene.solver);
    const auto insideABody = [&](const Vec3d& x, double margin) {
        for (std::size_t b = sceneryCount(scene); b < bodies.size(); ++b)
            if (bodies[b].signedDistance(x) < margin)
                return true;
        return false;
    };
    const double dx = scene.solver.particleSpacing;
    const double gravity = -scene.solver.gravity.y();
    const Aabb domain = scene.domain();
    ParticleSet& fluid = state.fluid;
    for (std::size_t block = 0; block < scene.fluidBlocks.size(); ++block) {
        const FluidBlock& b = scene.fluidBlocks[block];
        Vec3i count;
        for (int axis = 0; axis < 3; ++axis)
            count[axis] = b.layers(axis, dx, domain.max[axis]);
        const Vec3f velocity = b.initialVelocity.cast<float>();
        // The water's surface is the lattice's top, which differs from the block's drawn top
        // when its height is not whole spacings (the validator says so): the hydrostatic start
        // counts depth from where the water is.
        const double surface = b.min.y() + count.y() * dx;
        for (int k = 0; k < count.z(); ++k)
            for (int j = 0; j < count.y(); ++j)
                for (int i = 0; i < count.x(); ++i) {
                    const Vec3d x = b.min + (Vec3d(i, j, k) + Vec3d::Constant(0.5)) * dx;
                    if (!domain.contains(x) || insideAnyEarlierBlock(scene, block, x) ||
                        insideAnyObstacle(scene, x, 0.5 * dx) || insideABody(x, 0.25 * dx))
                        continue;
                    const double depth = std::max(0.0, surface - x.y());
                    const float density = equationOfState.densityForPressure(
                        scene.solver.restDensity * gravity * depth);
                    fluid.push(x.cast<float>(), velocity, density, state.nextParticleId++);
                }
    }
}

} // namespace airtrap
