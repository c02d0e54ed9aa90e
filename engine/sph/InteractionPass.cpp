#include "sph/InteractionPass.h"

#include "core/Parallel.h"
#include "sph/BoundaryNeighbors.h"

#include <algorithm>
#include <cmath>
#include <tbb/blocked_range.h>

namespace airtrap {

namespace {
using Range = tbb::blocked_range<std::size_t>;
constexpr std::size_t kGrain = 512;
} // namespace

InteractionPass::InteractionPass(const CubicSplineKernel& kernel,
                                 const InteractionConstants& constants)
    : kernel_(kernel), constants_(constants), contact_(constants.mass),
      radius2_(kernel.supportRadius() * kernel.supportRadius()),
      // Keeps μ of the artificial viscosity finite for coincident particles (0.01h², Monaghan).
      eta2_(0.01f * kernel.smoothingLength() * kernel.smoothingLength()) {}

void InteractionPass::densityRates(const InteractionInputs& in, std::vector<float>& rates,
                                   NeighborList& neighbors) const {
    neighbors.build(in.fluid.size(), [&](std::size_t i, NeighborList::Sink& sink) {
        const Vec3f vi = in.fluid.velocities[i];
        float rate = 0.0f;
        sweepNeighbors(in.grid, in.positions, i, radius2_,
                       [&](std::uint32_t j, const Vec3f& d, float r2) {
                           const Vec3f grad = kernel_.gradientFromSquared(d, r2);
                           rate += (vi - in.fluid.velocities[j]).dot(grad);
                           sink.add(j);
                       });
        rates[i] = constants_.mass * rate + boundaryDensityRate(i, in);
    });
}

float InteractionPass::boundaryDensityRate(std::size_t i, const InteractionInputs& in) const {
    const Vec3f vi = in.fluid.velocities[i];
    float rate = 0.0f;
    forEachBoundaryNeighbor(
        in.boundary, kernel_.supportRadius(), i, in.positions[i],
        [&](const BoundaryLayer& layer, std::uint32_t b, const Vec3f& d, float r2) {
            rate += layer.psi()[b] *
                    (vi - layer.velocities()[b]).dot(kernel_.gradientFromSquared(d, r2));
        });
    return rate;
}

double InteractionPass::accelerations(const InteractionInputs& in, const NeighborList& neighbors,
                                      const std::vector<float>& pressureTerms, double dt,
                                      std::vector<Vec3f>& accelerations,
                                      ContactRecords* contacts) const {
    const float step = static_cast<float>(dt);
    return parallelReduce(
        Range(0, in.fluid.size(), kGrain), 0.0,
        [&](const Range& r, double largest) {
            for (std::size_t i = r.begin(); i != r.end(); ++i) {
                BoundaryContact::Nearest contact;
                Vec3f acceleration = constants_.mass * waterForce(i, in, neighbors, pressureTerms) +
                                     constants_.gravity +
                                     boundaryForce(i, in, pressureTerms[i], contact);
                // The impulse is left out of the time-step criterion: it is a velocity change
                // applied once, not a force the step must resolve.
                largest = std::max(largest, double(acceleration.norm()));
                Vec3f impulse = Vec3f::Zero();
                if (contact.boundaryParticle >= 0) {
                    impulse = contact_.impulse(in.fluid.velocities[i], acceleration, contact,
                                               in.boundary, step);
                    acceleration += impulse / (constants_.mass * step);
                }
                accelerations[i] = acceleration;
                if (contacts)
                    BoundaryContact::record(i, contact, impulse, in.boundary, *contacts);
            }
            return largest;
        },
        [](double a, double b) { return std::max(a, b); });
}

Vec3f InteractionPass::waterForce(std::size_t i, const InteractionInputs& in,
                                  const NeighborList& neighbors,
                                  const std::vector<float>& pressureTerms) const {
    const Vec3f xi = in.positions[i];
    const Vec3f vi = in.fluid.velocities[i];
    const float rhoi = in.fluid.densities[i];
    const float pi = pressureTerms[i];
    Vec3f force = Vec3f::Zero();
    const auto addPair = [&](std::uint32_t j, const Vec3f& d, float r2) {
        const Vec3f grad = kernel_.gradientFromSquared(d, r2);
        const Vec3f vij = vi - in.fluid.velocities[j];
        const float approach = vij.dot(d);
        float viscosity = 0.0f; // Monaghan's Π with β = 0, only for approaching pairs
        if (approach < 0.0f) {
            const float rhoBar = 0.5f * (rhoi + in.fluid.densities[j]);
            viscosity = -constants_.fluidViscosity * approach / ((r2 + eta2_) * rhoBar);
        }
        force -= (pi + pressureTerms[j] + viscosity) * grad;
    };
    const std::uint32_t* list = neighbors.neighbors(i);
    for (std::uint32_t k = 0, n = neighbors.count(i); k < n; ++k) {
        const std::uint32_t j = list[k];
        const Vec3f d = xi - in.positions[j];
        addPair(j, d, d.squaredNorm());
    }
    return force;
}

Vec3f InteractionPass::boundaryForce(std::size_t i, const InteractionInputs& in, float pressureTerm,
                                     BoundaryContact::Nearest& contact) const {
    const Vec3f xi = in.positions[i];
    const Vec3f vi = in.fluid.velocities[i];
    const float rhoi = in.fluid.densities[i];
    contact.distance2 = constants_.contactRadius * constants_.contactRadius;
    Vec3f force = Vec3f::Zero();
    forEachBoundaryNeighbor(
        in.boundary, kernel_.supportRadius(), i, xi,
        [&](const BoundaryLayer& layer, std::uint32_t b, const Vec3f& d, float r2) {
            force += boundaryPairAcceleration(xi, vi, rhoi, pressureTerm, b, d, r2, layer);
            contact.consider(layer, b, r2);
        });
    return force;
}

Vec3f InteractionPass::boundaryPairAcceleration(const Vec3f& xi, const Vec3f& vi, float rhoi,
                                                float pressureTerm, std::size_t b, const Vec3f& d,
                                                float r2, const BoundaryLayer& layer) const {
    const Vec3f grad = kernel_.gradientFromSquared(d, r2);
    const float approach = (vi - layer.velocities()[b]).dot(d);
    float viscosity = 0.0f;
    if (approach < 0.0f)
        viscosity = -constants_.wallViscosity * approach / ((r2 + eta2_) * rhoi);
    // The wall's pressure is the particle's, extrapolated hydrostatically to the wall particle
    // (Adami et al. 2012), so that a floor carries the weight of the layer above it instead of
    // half of it.
    const float pressurei = pressureTerm * rhoi * rhoi;
    const float wallPressure =
        std::max(0.0f, pressurei + rhoi * constants_.gravity.dot(layer.positions()[b] - xi));
    return -layer.psi()[b] * (pressureTerm + wallPressure / (rhoi * rhoi) + viscosity) * grad;
}

void InteractionPass::bodyReactions(const InteractionInputs& in,
                                    const std::vector<float>& pressureTerms,
                                    const ContactRecords& contacts, double dt,
                                    std::vector<Vec3d>& forces) const {
    const BoundaryModel& boundary = in.boundary;
    const BoundaryLayer& layer = boundary.movingLayer();
    forces.assign(layer.size(), Vec3d::Zero());
    const float inverseStep = static_cast<float>(1.0 / dt);
    // Each boundary particle sums only its own pairs, in the water's sorted order: parallel and
    // deterministic, like the water's passes.
    parallelFor(Range(0, layer.size(), kGrain), [&](const Range& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            if (!boundary.contactTerms(layer.bodyOf()[b]).dynamic)
                continue;
            const Vec3f xb = layer.positions()[b];
            Vec3f force = Vec3f::Zero();
            // The pairs the force pass met, from this boundary particle's side, in the water's
            // sorted order.
            for (std::uint32_t i : boundary.movingPairs().waterNear(b)) {
                const Vec3f xi = in.positions[i];
                const Vec3f d = xi - xb;
                const float r2 = d.squaredNorm();
                if (r2 >= radius2_)
                    continue;
                force -= constants_.mass *
                         boundaryPairAcceleration(xi, in.fluid.velocities[i], in.fluid.densities[i],
                                                  pressureTerms[i], b, d, r2, layer);
                if (contacts.boundaryParticle[i] == static_cast<std::int32_t>(b))
                    force -= inverseStep * contacts.impulse[i];
            }
            forces[b] = force.cast<double>();
        }
    });
}

} // namespace airtrap
