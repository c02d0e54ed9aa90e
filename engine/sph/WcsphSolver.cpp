#include "sph/WcsphSolver.h"

#include "core/Error.h"
#include "core/Parallel.h"
#include "core/ParallelMax.h"
#include "sph/CellSort.h"
#include "sph/FrameLanding.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <tbb/blocked_range.h>

namespace airtrap {

namespace {

constexpr std::size_t kParticleGrain = 1024;

using Range = tbb::blocked_range<std::size_t>;

} // namespace

WcsphSolver::WcsphSolver(const SolverSettings& settings, const Aabb& domain)
    : settings_(settings),
      kernel_(static_cast<float>(settings.supportFactor * settings.particleSpacing)),
      spacing_(static_cast<float>(settings.particleSpacing)),
      mass_(static_cast<float>(settings.restDensity * std::pow(settings.particleSpacing, 3))),
      equationOfState_(settings),
      // The grid reaches one support radius beyond the domain so that the boundary layer, which
      // sits half a spacing outside the container's walls, is inside it.
      gridDomain_(domain.expanded(kernel_.supportRadius())),
      boundary_(gridDomain_, kernel_.supportRadius(), static_cast<float>(settings.restDensity)),
      grid_(gridDomain_, kernel_.supportRadius()), passes_(kernel_, interactionConstants()) {}

InteractionConstants WcsphSolver::interactionConstants() const {
    const float c = static_cast<float>(equationOfState_.speedOfSound());
    const float h = kernel_.smoothingLength();
    InteractionConstants constants;
    constants.mass = mass_;
    constants.fluidViscosity = static_cast<float>(settings_.viscosityAlpha) * c * h;
    constants.wallViscosity = static_cast<float>(settings_.wallViscosity) * c * h;
    // Water rests one spacing from the boundary layer; half of that is a real contact.
    constants.contactRadius = 0.5f * spacing_;
    constants.gravity = settings_.gravity.cast<float>();
    return constants;
}

void WcsphSolver::pairMovingBoundary() {
    if (boundary_.movingLayer().size() > 0)
        boundary_.findMovingLayerPairs(grid_, sortedPositions_, kernel_.supportRadius());
}

InteractionInputs WcsphSolver::inputs(const ParticleSet& fluid) const {
    return InteractionInputs{fluid, sortedPositions_, grid_, boundary_};
}

void WcsphSolver::computeDensities(ParticleSet& fluid, std::uint64_t step, double dt,
                                   StepReport& report) {
    const int interval = settings_.shepardInterval;
    if (interval > 0 && step > 0 && step % interval == 0)
        shepardFilter(fluid);
    densityRates_.resize(fluid.size());
    passes_.densityRates(inputs(fluid), densityRates_, neighbors_);
    report.maxDensityDeviation = advanceDensities(fluid, dt);
}

void WcsphSolver::computeForces(const ParticleSet& fluid, double dt, StepReport& report) {
    accelerations_.resize(fluid.size());
    const bool recordContacts = boundary_.hasDynamicBodies();
    if (recordContacts)
        contacts_.resize(fluid.size());
    report.maxAcceleration =
        passes_.accelerations(inputs(fluid), neighbors_, pressureOverDensity2_, dt, accelerations_,
                              recordContacts ? &contacts_ : nullptr);
}

void WcsphSolver::computeBodyReactions(const ParticleSet& fluid, double dt) {
    passes_.bodyReactions(inputs(fluid), pressureOverDensity2_, contacts_, dt, reactions_);
}

void WcsphSolver::placeBoundary(const std::vector<RigidBody>& bodies, std::size_t firstBubble) {
    boundary_.rebuild(bodies, firstBubble);
}

void WcsphSolver::sortByCell(ParticleSet& fluid, StepReport& report) {
    // The accelerations and the density rates are rewritten before this step reads them.
    airtrap::sortByCell(grid_, fluid, SortSpares{accelerations_, densityRates_, sortIds_},
                        sortedPositions_, report);
}

double WcsphSolver::advanceDensities(ParticleSet& fluid, double dt) {
    const std::size_t n = fluid.size();
    pressureOverDensity2_.resize(n);
    const float step = static_cast<float>(dt);
    const float restDensity = static_cast<float>(settings_.restDensity);
    const double invRest = 1.0 / settings_.restDensity;
    return parallelMax(n, [&](std::size_t i) {
        // Water does not expand: below ρ₀ the clamped pressure could not push back, and a
        // particle that drifted low would let its neighbours clump onto it when the flow
        // converges again (the clamp SPlisHSPlasH applies before its equation of state).
        const float rho = std::max(restDensity, fluid.densities[i] + step * densityRates_[i]);
        fluid.densities[i] = rho;
        pressureOverDensity2_[i] = equationOfState_.pressure(rho) / (rho * rho);
        return std::abs(rho * invRest - 1.0);
    });
}

void WcsphSolver::chooseTimeStep(double lastMaxAcceleration, double timeToFrameEnd,
                                 StepReport& report) const {
    const double h = kernel_.smoothingLength();
    double dt = settings_.cflFactor * h / (equationOfState_.speedOfSound() + report.maxSpeed);
    if (lastMaxAcceleration > 0.0)
        dt = std::min(dt, 0.25 * std::sqrt(h / lastMaxAcceleration));
    report.timeStep = landOnFrame(dt, timeToFrameEnd);
}

void WcsphSolver::shepardFilter(ParticleSet& fluid) {
    // ρᵢ = Σⱼ mⱼWᵢⱼ / Σⱼ (mⱼ/ρⱼ)Wᵢⱼ over the water, the particle itself included (docs/METHOD.md
    // "Density (eq. 2) and Shepard re-initialisation"): removes the slow drift of the continuity
    // density without the surface deficiency of a plain summation.
    const std::size_t n = fluid.size();
    const float radius2 = kernel_.supportRadius() * kernel_.supportRadius();
    const float selfWeight = kernel_.value(0.0f);
    std::vector<float>& filtered = densityRates_; // free until the density pass
    filtered.resize(n);
    parallelFor(Range(0, n, kParticleGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            float weight = selfWeight;
            float weightOverDensity = selfWeight / fluid.densities[i];
            sweepNeighbors(grid_, sortedPositions_, i, radius2,
                           [&](std::uint32_t j, const Vec3f&, float r2) {
                               const float w = kernel_.value(std::sqrt(r2));
                               weight += w;
                               weightOverDensity += w / fluid.densities[j];
                           });
            filtered[i] = weight / weightOverDensity;
        }
    });
    fluid.densities.swap(filtered);
}

bool WcsphSolver::integrate(ParticleSet& fluid, double dt) {
    const float step = static_cast<float>(dt);
    std::atomic<bool> nonFinite{false};
    parallelFor(Range(0, fluid.size(), kParticleGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            // Symplectic Euler: the new velocity moves the particle.
            fluid.velocities[i] += step * accelerations_[i];
            fluid.positions[i] += step * fluid.velocities[i];
            if (!fluid.positions[i].allFinite() || !fluid.velocities[i].allFinite() ||
                !std::isfinite(fluid.densities[i]))
                nonFinite.store(true, std::memory_order_relaxed);
        }
    });
    return nonFinite.load();
}

std::size_t WcsphSolver::allocatedBytes() const {
    return grid_.allocatedBytes() + boundary_.allocatedBytes() + sortedPositions_.allocatedBytes() +
           neighbors_.allocatedBytes() + pressureOverDensity2_.capacity() * sizeof(float) +
           densityRates_.capacity() * sizeof(float) + accelerations_.capacity() * sizeof(Vec3f) +
           sortIds_.capacity() * sizeof(std::uint32_t) + contacts_.allocatedBytes() +
           reactions_.capacity() * sizeof(Vec3d);
}

} // namespace airtrap
