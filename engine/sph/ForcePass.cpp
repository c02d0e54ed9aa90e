#include "sph/ForcePass.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <tbb/blocked_range.h>
#include <tbb/parallel_reduce.h>

namespace airtrap {

struct ForcePass::Inputs {
    const ParticleSet& fluid;
    const PositionArrays& positions;
    const std::vector<float>& pressureOverDensity2;
    const NeighborGrid& grid;
    const BoundaryModel& boundary;
    float dt;
};

ForcePass::ForcePass(const CubicSplineKernel& kernel, const ForceConstants& constants)
    : kernel_(kernel), constants_(constants),
      radius2_(kernel.supportRadius() * kernel.supportRadius()),
      // Keeps μ of the artificial viscosity finite for coincident particles (0.01h², Monaghan).
      eta2_(0.01f * kernel.smoothingLength() * kernel.smoothingLength()) {}

double ForcePass::run(const ParticleSet& fluid, const PositionArrays& sortedPositions,
                      const std::vector<float>& pressureOverDensity2, const NeighborGrid& grid,
                      const BoundaryModel& boundary, double dt, std::vector<float>& densityRates,
                      std::vector<Vec3f>& accelerations) const {
    const Inputs in{fluid, sortedPositions, pressureOverDensity2,
                    grid,  boundary,        static_cast<float>(dt)};
    using Range = tbb::blocked_range<std::size_t>;
    return tbb::parallel_reduce(
        Range(0, fluid.size(), 512), 0.0,
        [&](const Range& r, double largest) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                Vec3f force = Vec3f::Zero();
                float drho = fluidTerms(i, in, force);
                Vec3f acceleration = constants_.mass * force + constants_.gravity;
                Contact contact;
                drho += boundaryTerms(i, in, acceleration, contact);
                // The impulse is left out of the time-step criterion: it is a velocity change
                // applied once, not a force the step must resolve.
                largest = std::max(largest, double(acceleration.norm()));
                if (contact.boundaryParticle >= 0)
                    acceleration +=
                        contactImpulse(fluid.velocities[i], acceleration, contact, boundary, in.dt);
                densityRates[i] = drho;
                accelerations[i] = acceleration;
            }
            return largest;
        },
        [](double a, double b) { return std::max(a, b); });
}

float ForcePass::fluidTerms(std::size_t i, const Inputs& in, Vec3f& force) const {
    // Two stages: a branch-free sweep over the 27 cells keeps the candidates inside the support
    // (most of the time goes here, so it only reads the three coordinate arrays), then the SPH
    // sums over the few that remain.
    constexpr std::size_t kBatch = 256;
    std::array<std::uint32_t, kBatch> neighbor;
    std::array<float, kBatch> distance2;
    const float* px = in.positions.x.data();
    const float* py = in.positions.y.data();
    const float* pz = in.positions.z.data();
    const Vec3f xi(px[i], py[i], pz[i]);
    const Vec3f vi = in.fluid.velocities[i];
    const float rhoi = in.fluid.densities[i];
    const float pi = in.pressureOverDensity2[i];
    float drho = 0.0f;
    std::size_t count = 0;

    const auto interact = [&] {
        for (std::size_t k = 0; k < count; ++k) {
            const std::uint32_t j = neighbor[k];
            const Vec3f d(xi.x() - px[j], xi.y() - py[j], xi.z() - pz[j]);
            const Vec3f grad = kernel_.gradient(d, std::sqrt(distance2[k]));
            const Vec3f vij = vi - in.fluid.velocities[j];
            drho += vij.dot(grad);
            const float approach = vij.dot(d);
            float viscosity = 0.0f;
            if (approach < 0.0f) {
                const float rhoBar = 0.5f * (rhoi + in.fluid.densities[j]);
                viscosity =
                    -constants_.fluidViscosity * approach / ((distance2[k] + eta2_) * rhoBar);
            }
            force -= (pi + in.pressureOverDensity2[j] + viscosity) * grad;
        }
        count = 0;
    };

    in.grid.forEachNeighborRange(xi, [&](std::uint32_t begin, std::uint32_t end) {
        if (count + (end - begin) > kBatch)
            interact();
        for (std::uint32_t j = begin; j < end; ++j) {
            const float dx = xi.x() - px[j];
            const float dy = xi.y() - py[j];
            const float dz = xi.z() - pz[j];
            const float r2 = dx * dx + dy * dy + dz * dz;
            neighbor[count] = j;
            distance2[count] = r2;
            count += (r2 < radius2_) & (j != i);
        }
    });
    interact();
    return constants_.mass * drho;
}

float ForcePass::boundaryTerms(std::size_t i, const Inputs& in, Vec3f& acceleration,
                               Contact& contact) const {
    const BoundaryModel& boundary = in.boundary;
    if (boundary.size() == 0)
        return 0.0f;
    const auto& bx = boundary.positions();
    const auto& bv = boundary.velocities();
    const auto& bpsi = boundary.psi();
    const Vec3f xi(in.positions.x[i], in.positions.y[i], in.positions.z[i]);
    const Vec3f vi = in.fluid.velocities[i];
    const float rhoi = in.fluid.densities[i];
    const float pi = in.pressureOverDensity2[i];
    const float pressurei = pi * rhoi * rhoi;
    contact.distance2 = constants_.contactRadius * constants_.contactRadius;
    float drho = 0.0f;
    Vec3f fluidForce = Vec3f::Zero();

    boundary.grid().forEachNeighborRange(xi, [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t b = begin; b < end; ++b) {
            const Vec3f d = xi - bx[b];
            const float r2 = d.squaredNorm();
            if (r2 >= radius2_)
                continue;
            const Vec3f grad = kernel_.gradient(d, std::sqrt(r2));
            const Vec3f vib = vi - bv[b];
            drho += bpsi[b] * vib.dot(grad);
            const float approach = vib.dot(d);
            float viscosity = 0.0f;
            if (approach < 0.0f)
                viscosity = -constants_.wallViscosity * approach / ((r2 + eta2_) * rhoi);
            // The wall's pressure is the particle's, extrapolated hydrostatically to the wall
            // particle (Adami et al. 2012), so that a floor carries the weight of the layer above
            // it instead of half of it.
            const float wallPressure =
                std::max(0.0f, pressurei + rhoi * constants_.gravity.dot(bx[b] - xi));
            fluidForce -= bpsi[b] * (pi + wallPressure / (rhoi * rhoi) + viscosity) * grad;
            if (r2 < contact.distance2) {
                contact.distance2 = r2;
                contact.boundaryParticle = b;
            }
        }
    });
    acceleration += fluidForce;
    return drho;
}

Vec3f ForcePass::contactImpulse(const Vec3f& velocity, const Vec3f& acceleration,
                                const Contact& contact, const BoundaryModel& boundary,
                                float dt) const {
    const std::size_t b = static_cast<std::size_t>(contact.boundaryParticle);
    const Vec3f& normal = boundary.normals()[b];
    const Vec3f predicted = velocity + dt * acceleration - boundary.velocities()[b];
    const float normalSpeed = predicted.dot(normal);
    if (normalSpeed >= 0.0f)
        return Vec3f::Zero();
    return (-(1.0f + constants_.restitution) * normalSpeed / dt) * normal;
}

} // namespace airtrap
