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

} // namespace

std::vector<RigidBody> SceneSetup::buildBodies(const Scene& scene) {
    const double dx = scene.solver.particleSpacing;
    const CubicSplineKernel kernel(static_cast<float>(scene.supportRadius()));
    std::vector<RigidBody> bodies;

    const Aabb tank = Aabb{scene.container.min, scene.container.max}.expanded(0.5 * dx);
    BoundaryParticles walls =
        BoundarySampler::sampleBox(tank, dx, BoundarySampler::WaterSide::Inside, true);
    BoundarySampler::computeVolumes(walls, kernel, dx);
    bodies.emplace_back("Container", RigidBody::Motion::Static, std::move(walls));

    for (const BoxObstacle& obstacle : scene.obstacles) {
        BoundaryParticles surface =
            BoundarySampler::sampleBox(obstacleBox(obstacle).expanded(0.5 * dx), dx,
                                       BoundarySampler::WaterSide::Outside, false);
        BoundarySampler::computeVolumes(surface, kernel, dx);
        bodies.emplace_back(obstacle.name, RigidBody::Motion::Static, std::move(surface));
    }
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
