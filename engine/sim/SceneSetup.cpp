#include "sim/SceneSetup.h"

#include "rigid/BoundarySampler.h"
#include "sph/WcsphSolver.h"

#include <cmath>

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

//! A static box body whose frame sits at the box's centre, sampled on its surface.
RigidBody boxBody(const std::string& name, const Aabb& box, double spacing,
                  BoundarySampler::WaterSide side, bool openTop, const CubicSplineKernel& kernel) {
    const Vec3d half = 0.5 * box.size();
    BoundaryParticles surface = BoundarySampler::sampleBox({-half, half}, spacing, side, openTop);
    BoundarySampler::computeVolumes(surface, kernel, spacing);
    return RigidBody(name, RigidBody::Motion::Static, std::move(surface), box.center());
}

} // namespace

std::vector<RigidBody> SceneSetup::buildBodies(const Scene& scene) {
    const double dx = scene.solver.particleSpacing;
    const CubicSplineKernel kernel(static_cast<float>(scene.supportRadius()));
    std::vector<RigidBody> bodies;
    const Aabb tank = Aabb{scene.container.min, scene.container.max}.expanded(0.5 * dx);
    bodies.push_back(
        boxBody("Container", tank, dx, BoundarySampler::WaterSide::Inside, true, kernel));
    for (const BoxObstacle& obstacle : scene.obstacles)
        bodies.push_back(boxBody(obstacle.name, obstacleBox(obstacle).expanded(0.5 * dx), dx,
                                 BoundarySampler::WaterSide::Outside, false, kernel));
    return bodies;
}

void SceneSetup::fillFluid(const Scene& scene, const WcsphSolver& solver, SimulationState& state) {
    const double dx = scene.solver.particleSpacing;
    const double gravity = -scene.solver.gravity.y();
    const Aabb domain = scene.domain();
    ParticleSet& fluid = state.fluid;
    for (std::size_t block = 0; block < scene.fluidBlocks.size(); ++block) {
        const FluidBlock& b = scene.fluidBlocks[block];
        Vec3i count;
        for (int axis = 0; axis < 3; ++axis)
            count[axis] = std::max(1, static_cast<int>(std::lround((b.max - b.min)[axis] / dx)));
        const Vec3f velocity = b.initialVelocity.cast<float>();
        for (int k = 0; k < count.z(); ++k)
            for (int j = 0; j < count.y(); ++j)
                for (int i = 0; i < count.x(); ++i) {
                    const Vec3d x = b.min + (Vec3d(i, j, k) + Vec3d::Constant(0.5)) * dx;
                    if (!domain.contains(x) || insideAnyEarlierBlock(scene, block, x) ||
                        insideAnyObstacle(scene, x, 0.5 * dx))
                        continue;
                    const double depth = std::max(0.0, b.max.y() - x.y());
                    const float density =
                        solver.densityForPressure(scene.solver.restDensity * gravity * depth);
                    fluid.push(x.cast<float>(), velocity, density, state.nextParticleId++);
                }
    }
}

} // namespace airtrap
