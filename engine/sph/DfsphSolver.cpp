#include "sph/DfsphSolver.h"

#include "core/DeterministicSum.h"
#include "core/Parallel.h"
#include "core/ParallelMax.h"
#include "sph/BoundaryNeighbors.h"
#include "sph/CellSort.h"
#include "sph/ChebyshevWeights.h"
#include "sph/FrameLanding.h"

#include <algorithm>
#include <array>
#include <atomic>
#if defined(__SSE2__)
#include <emmintrin.h>
#elif defined(__ARM_NEON)
#include <arm_neon.h>
#endif
#include <cmath>
#include <cstdint>
#include <limits>
#include <tbb/blocked_range.h>

namespace airtrap {

namespace {

using Range = tbb::blocked_range<std::size_t>;
constexpr std::size_t kSolveGrain = 512;
//! The split of the deterministic sums: fixed, so every run adds in the same order.
constexpr std::size_t kSolveSumGrain = 4096;

//! A particle with fewer neighbours than this (water and boundary; 26 on the resting lattice)
//! sits at the free surface, where the velocity may diverge: the divergence solve leaves it
//! alone, as Bender & Koschier's implementation does, or it would glue splashes to the water.
constexpr std::uint32_t kInteriorNeighbours = 20;
//! The wall pushes back with the particle's own pressure on both sides of the pair, as if mirrored
//! (pᵢ/ρᵢ² + p_b/ρ_b² with p_b = pᵢ), as WCSPH's walls do by extrapolating it (Adami et al. 2012):
//! with one side only (Akinci et al. 2012), the bottom layer of a resting pool is pushed into the
//! floor by the column above at every step.
constexpr float kWallPressureShare = 2.0f;
//! Share of the last step's divergence stiffness the next step starts from: the compression
//! the divergence solve removes comes mostly from the last step's residual, which the full value
//! would overshoot (and an overshoot cannot be pulled back: its residual is clamped at zero).
constexpr float kDivergenceWarmShare = 0.5f;
//! The density solve starts from the whole of the last step's stiffness: in a deep pool most of it
//! is the column's weight, which a Jacobi solve rebuilds only over many iterations. Its iterations
//! may lower a stiffness (down to zero) where the water has since expanded.
constexpr float kDensityWarmShare = 1.0f;
//! Under-relaxation of the density solve's Jacobi update: with the full update a signed
//! iteration overshoots the pair-wise coupled stiffness (a resting tank blew up, measured); half
//! of it keeps the Jacobi iteration's eigenvalues within [0, 1), where Chebyshev acceleration
//! applies.
constexpr float kDensityRelaxation = 0.5f;
//! The Jacobi iteration's spectral radius the density solve accelerates for (ChebyshevWeights).
//! Measured: 0.98 cuts the iterations per step by about four (docs/VALIDATION.md "Divergence-free
//! SPH"); 0.99 leaves the violent first steps of a dam break oscillating at max_iterations, 0.995
//! diverges.
constexpr float kDensitySpectralRadius = 0.98f;
//! The density solve's overshoot (expansion where a stiffness still pushes) may average this many
//! times the error target while the compression is within the target. The target bounds
//! compression, as in Bender & Koschier's solver; an overshoot is no compression, but left
//! unbounded it shakes resting water. Measured on the first 0.2 s of
//! samples/bench/peer_dam_break.json and the hydrostatic tank (docs/VALIDATION.md "Divergence-free
//! SPH"): both held to the target, 22.6 density iterations per step, rms 0.012 m/s; 3 times,
//! 15.3 and 0.011; 5 times, 14.7 and 0.021; unbounded, 12.9 and 0.025 (the test allows 0.02).
constexpr double kOvershootAllowance = 3.0;
//! A residual this many times the lowest of the solve so far means the acceleration is amplifying
//! a component beyond the assumed radius: the next iterate is a plain Jacobi one again.
constexpr double kChebyshevRestartGrowth = 2.0;

//! A dynamic body moves at most this share of a spacing per step. The density solve predicts the
//! compression a step leaves to first order; a body closing on a wall squeezes the water between
//! them far beyond that prediction when it moves a sizeable share of a spacing per step, and the
//! next solve removes the excess at once, as a speed excess/Δt that throws the body back: the
//! 10ρ cube of samples/buoyancy.json landed at 1.4 m/s and bounced up at 2–3 m/s under the
//! flow's step alone (0.25 spacings per step), 0.28 m/s at 0.05 and landed on another face at 0.2
//! (docs/VALIDATION.md "Bodies with DFSPH"). Bubbles are not held to it: their vertical speed is
//! steered and their drag pulls them toward the water's velocity, both implicitly (eqs. 5, 6), so
//! they move with the water rather than squeeze it, and a bubble swept along by a jet would
//! otherwise set the step of the whole tank (docs/METHOD.md "Bodies and the step").
constexpr double kBodyCflFactor = 0.05;

using Vec2d = Eigen::Vector2d;

struct Fastest {
    double speed = 0.0;
    std::size_t particle = SIZE_MAX;
};

//! The largest speed(i) over [0, n) and the first particle that has it: the same on any number
//! of threads.
template <class Speed>
Fastest findFastest(std::size_t n, Speed&& speed) {
    const auto faster = [](const Fastest& a, const Fastest& b) {
        if (a.speed != b.speed)
            return a.speed > b.speed ? a : b;
        return a.particle < b.particle ? a : b;
    };
    return parallelReduce(
        Range(0, n, kSolveSumGrain), Fastest{},
        [&](const Range& r, Fastest best) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
                best = faster(best, Fastest{static_cast<double>(speed(i)), i});
            return best;
        },
        faster);
}

} // namespace

DfsphSolver::DfsphSolver(const SolverSettings& settings, const Aabb& domain)
    : settings_(settings),
      kernel_(static_cast<float>(settings.supportFactor * settings.particleSpacing)),
      spacing_(static_cast<float>(settings.particleSpacing)),
      mass_(static_cast<float>(settings.restDensity * std::pow(settings.particleSpacing, 3))),
      radius2_(kernel_.supportRadius() * kernel_.supportRadius()),
      // Water rests one spacing from the boundary layer; half of that is a real contact.
      contactRadius_(0.5f * spacing_), gridDomain_(domain.expanded(kernel_.supportRadius())),
      boundary_(gridDomain_, kernel_.supportRadius(), static_cast<float>(settings.restDensity)),
      grid_(gridDomain_, kernel_.supportRadius()), contact_(mass_),
      bodies_(kernel_, mass_, static_cast<float>(settings.restDensity), kWallPressureShare) {}

void DfsphSolver::sortByCell(ParticleSet& fluid, StepReport& report) {
    // The boundary gradients and the stiffness increments are rewritten before this step reads
    // them.
    airtrap::sortByCell(grid_, fluid, SortSpares{boundaryGradient_, stiffness_, sortIds_},
                        sortedPositions_, report);
}

void DfsphSolver::placeBoundary(const std::vector<RigidBody>& bodies, std::size_t firstBubble) {
    boundary_.rebuild(bodies, firstBubble);
}

void DfsphSolver::pairMovingBoundary() {
    if (boundary_.movingLayer().size() > 0)
        boundary_.findMovingLayerPairs(grid_, sortedPositions_, kernel_.supportRadius());
}

namespace {
using CodeFloats = float __attribute__((vector_size(16)));

//! codes[0..3] as floats: widened and converted in two vector instructions (SSE2 or NEON),
//! which compilers do not find by themselves for 16-bit lanes.
CodeFloats fourFactorCodes(const NeighborList::Value* codes) {
#if defined(__SSE2__)
    const __m128i quad = _mm_loadl_epi64(reinterpret_cast<const __m128i*>(codes));
    return _mm_cvtepi32_ps(_mm_unpacklo_epi16(quad, _mm_setzero_si128()));
#elif defined(__ARM_NEON)
    CodeFloats factors;
    vst1q_f32(reinterpret_cast<float*>(&factors), vcvtq_f32_u32(vmovl_u16(vld1_u16(codes))));
    return factors;
#else
    return CodeFloats{float(codes[0]), float(codes[1]), float(codes[2]), float(codes[3])};
#endif
}
} // namespace

template <class Term>
Vec4f DfsphSolver::sumOverWaterGradients(std::size_t i, Term&& term) const {
    // Local pointers and a local sum: with a sum written through a reference at every pair, the
    // compiler must assume the store may change the arrays, and reloads them (measured: the
    // loop ran at the speed of that store, half the speed of this one).
    const Vec4f* positions = packedPositions_.data();
    const Vec4f xi = positions[i];
    const std::uint32_t* list = neighbors_.neighbors(i);
    const NeighborList::Value* codes = neighbors_.values(i);
    const std::uint32_t count = neighbors_.count(i);
    Vec4f sum = Vec4f::Zero();
    std::uint32_t k = 0;
    // Four codes converted at once: one by one, the conversion doubled the floating-point work
    // that is not the pair's own and the passes ran 15–20 % slower than with stored floats.
    for (; k + 4 <= count; k += 4) {
        const CodeFloats factors = fourFactorCodes(codes + k);
        for (std::uint32_t t = 0; t < 4; ++t)
            sum += term(list[k + t], Vec4f(factors[t] * (xi - positions[list[k + t]])));
    }
    for (; k < count; ++k)
        sum += term(list[k], Vec4f(float(codes[k]) * (xi - positions[list[k]])));
    // The terms are linear in the gradient, so the codes' step scales the sum once.
    return kernel_.gradientFactorStep() * sum;
}

// ---- densities and factors -----------------------------------------------------------------

void DfsphSolver::prepareDensities(ParticleSet& fluid, StepReport& report) {
    const std::size_t n = fluid.size();
    packedPositions_.resize(n);
    velocities_.resize(n);
    unsmoothed_.resize(n);
    factors_.resize(n);
    interior_.resize(n);
    boundaryGradient_.resize(n);
    boundaryRate_.resize(n);
    nearestBoundary_.resize(n);
    nearestIsMoving_.resize(n);
    carryWarmStart(n);
    neighbors_.build(
        n, [&](std::size_t i, NeighborList::Sink& sink) { prepareParticle(fluid, i, sink); });
    const double restDensity = settings_.restDensity;
    // Compression only: a splash particle's summed density is far below ρ₀ without any fault.
    report.maxDensityDeviation = parallelMax(
        n, [&](std::size_t i) { return std::max(0.0, fluid.densities[i] / restDensity - 1.0); });
    bodies_.begin(boundary_, sortedPositions_, boundaryRate_);
}

void DfsphSolver::prepareParticle(ParticleSet& fluid, std::size_t i, NeighborList::Sink& sink) {
    velocities_[i] = padded(fluid.velocities[i]);
    packedPositions_[i] = padded(sortedPositions_[i]);
    WaterSums water{kernel_.value(0.0f)};
    sweepNeighborBatchesAround(grid_, sortedPositions_, sortedPositions_[i], radius2_,
                               [&](const std::uint32_t* batch, std::size_t size) {
                                   addWaterPairs(i, batch, size, water, sink);
                               });
    std::uint32_t count = water.count;

    float density = mass_ * water.weights;
    Vec3f boundaryGradient = Vec3f::Zero();
    float boundaryRate = 0.0f;
    BoundaryContact::Nearest nearest;
    nearest.distance2 = contactRadius_ * contactRadius_;
    forEachBoundaryNeighbor(
        boundary_, kernel_.supportRadius(), i, sortedPositions_[i],
        [&](const BoundaryLayer& layer, std::uint32_t b, const Vec3f& d, float r2) {
            const float psi = layer.psi()[b];
            const Vec3f grad = kernel_.gradientFromSquared(d, r2);
            density += psi * kernel_.value(std::sqrt(r2));
            boundaryGradient += psi * grad;
            boundaryRate += psi * layer.velocities()[b].dot(grad);
            nearest.consider(layer, b, r2);
            ++count;
        });
    fluid.densities[i] = density;
    boundaryGradient_[i] = boundaryGradient;
    boundaryRate_[i] = boundaryRate;
    nearestBoundary_[i] = static_cast<std::int32_t>(nearest.boundaryParticle);
    nearestIsMoving_[i] = nearest.layer == &boundary_.movingLayer();

    // αᵢ: how much qᵢ alone changes Dρᵢ/Dt, its own velocity and its neighbours' together.
    const Vec3f waterGradient = mass_ * water.gradientSum;
    const float denominator = (waterGradient + kWallPressureShare * boundaryGradient)
                                  .dot(waterGradient + boundaryGradient) +
                              mass_ * mass_ * water.gradientSquares;
    factors_[i] = denominator > 0.0f ? 1.0f / denominator : 0.0f;
    interior_[i] = count >= kInteriorNeighbours;
}

void DfsphSolver::addWaterPairs(std::size_t i, const std::uint32_t* batch, std::size_t size,
                                WaterSums& sums, NeighborList::Sink& sink) const {
    std::array<std::uint32_t, kSweepBatch> indices;
    std::array<Vec3f, kSweepBatch> offsets;
    // With room for the kernel's four-wide reads and writes past the count.
    std::array<float, kSweepBatch + 3> distance2;
    std::array<float, kSweepBatch + 3> weights;
    std::array<std::int32_t, kSweepBatch + 3> codes;
    std::array<NeighborList::Value, kSweepBatch> listed;
    const float* px = sortedPositions_.x.data();
    const float* py = sortedPositions_.y.data();
    const float* pz = sortedPositions_.z.data();
    const Vec3f xi = sortedPositions_[i];
    std::size_t kept = 0;
    for (std::size_t k = 0; k < size; ++k) {
        const std::uint32_t j = batch[k];
        if (j == i)
            continue;
        offsets[kept] = Vec3f(xi.x() - px[j], xi.y() - py[j], xi.z() - pz[j]);
        distance2[kept] = offsets[kept].squaredNorm();
        indices[kept++] = j;
    }
    std::fill(distance2.begin() + kept, distance2.begin() + kept + 3, 0.0f);
    // The kernel's values and codes first, for the batch at once; then the sums in pair order, in
    // registers: summed through the sweep's call per pair they stayed in memory, each addition
    // waiting on the last one's store.
    kernel_.valuesAndFactorCodes(distance2.data(), kept, weights.data(), codes.data());
    WaterSums local = sums;
    for (std::size_t k = 0; k < kept; ++k) {
        local.weights += weights[k];
        // α from the factor the solves' passes will read back.
        const auto code = static_cast<NeighborList::Value>(codes[k]);
        const Vec3f grad = (kernel_.gradientFactorStep() * float(code)) * offsets[k];
        local.gradientSum += grad;
        local.gradientSquares += grad.squaredNorm();
        listed[k] = code;
    }
    local.count += static_cast<std::uint32_t>(kept);
    sink.add(indices.data(), listed.data(), kept);
    sums = local;
}

void DfsphSolver::carryWarmStart(std::size_t n) {
    const auto& order = grid_.order();
    // Each total holds the last step's values in the last step's order; stiffness_ is free
    // until the solves.
    const auto carry = [&](std::vector<float>& total, float share) {
        stiffness_.resize(n);
        parallelFor(Range(0, n, kSolveGrain), [&](const Range& r) {
            for (std::size_t s = r.begin(); s != r.end(); ++s) {
                // Particles emitted since the last step have none.
                const std::uint32_t from = order[s];
                stiffness_[s] = from < total.size() ? share * total[from] : 0.0f;
            }
        });
        std::swap(total, stiffness_);
    };
    carry(divergenceTotal_, kDivergenceWarmShare);
    // Held as κ until the step is known: computeDensities() turns it into q = κ Δt.
    carry(densityTotal_, kDensityWarmShare);
    stiffness_.resize(n);
}

// ---- the solves ----------------------------------------------------------------------------

float DfsphSolver::densityRate(std::size_t i) const {
    const Vec4f vi = velocities_[i];
    // Summed per component and added up once: the pairs' products stay in one SIMD register.
    const Vec4f* velocities = velocities_.data();
    const Vec4f products = sumOverWaterGradients(i, [&](std::uint32_t j, const Vec4f& gradient) {
        return Vec4f((vi - velocities[j]).cwiseProduct(gradient));
    });
    return mass_ * products.sum() + vi.head<3>().dot(boundaryGradient_[i]) - boundaryRate_[i];
}

void DfsphSolver::storeDensityRates(bool interiorOnly) {
    parallelFor(Range(0, velocities_.size(), kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
            stiffness_[i] = interiorOnly && !interior_[i] ? 0.0f : densityRate(i);
    });
}

double DfsphSolver::divergenceResiduals() {
    const std::size_t n = velocities_.size();
    storeDensityRates(true);
    const double sum = deterministicSum(n, kSolveSumGrain, 0.0, [&](std::size_t i) {
        if (!interior_[i])
            return 0.0;
        // Compression only: expansion is the free surface's, not an error, and water does not
        // pull.
        const float rate = std::max(stiffness_[i], 0.0f);
        stiffness_[i] = rate * factors_[i];
        return double(rate);
    });
    return n > 0 ? sum / double(n) : 0.0;
}

DfsphSolver::Residual DfsphSolver::densityResiduals(float dt, const float* densities,
                                                    float chebyshevWeight) {
    const std::size_t n = velocities_.size();
    const float restDensity = static_cast<float>(settings_.restDensity);
    storeDensityRates(false);
    const Vec2d sums =
        deterministicSum(n, kSolveSumGrain, Vec2d(Vec2d::Zero()), [&](std::size_t i) {
            const float compression = densities[i] + dt * stiffness_[i] - restDensity;
            const float current = densityTotal_[i];
            // Water does not pull: the stiffness stays at or above zero (a complementarity problem,
            // solved by projecting each iterate).
            const float jacobi =
                std::max(current + kDensityRelaxation * compression * factors_[i] / dt, 0.0f);
            const float previous = previousDensityTotal_[i];
            const float next = std::max(chebyshevWeight * (jacobi - previous) + previous, 0.0f);
            previousDensityTotal_[i] = current;
            stiffness_[i] = next - current;
            // Compression left, or expansion where the water still pushes (an overshoot); expansion
            // with no stiffness is the free surface's.
            if (compression > 0.0f)
                return Vec2d(compression, 0.0);
            return Vec2d(0.0, current > 0.0f ? -compression : 0.0f);
        });
    if (n == 0)
        return {};
    return {sums.x() / double(n), sums.y() / double(n)};
}

void DfsphSolver::applyStiffness(const std::vector<float>& stiffness, std::vector<float>* total) {
    const std::size_t n = velocities_.size();
    parallelFor(Range(0, n, kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const float qi = stiffness[i];
            const float* q = stiffness.data();
            const Vec4f pairs =
                sumOverWaterGradients(i, [&](std::uint32_t j, const Vec4f& gradient) {
                    return Vec4f((qi + q[j]) * gradient);
                });
            velocities_[i] -=
                mass_ * pairs + padded((kWallPressureShare * qi) * boundaryGradient_[i]);
            if (total)
                (*total)[i] += qi;
        }
    });
}

DfsphSolver::Outcome DfsphSolver::iterate(Solve solve, float dt, double tolerance,
                                          std::vector<float>& total, const float* densities) {
    // The warm start: the stiffness carried over, inside the water only (at the free surface it
    // would push apart water that has since relaxed).
    parallelFor(Range(0, total.size(), kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
            if (!interior_[i])
                total[i] = 0.0f;
    });
    applyStiffness(total, nullptr);
    bodies_.startSolve();
    moveBodies(solve, dt);
    if (solve == Solve::Density)
        previousDensityTotal_.assign(total.begin(), total.end());
    ChebyshevWeights chebyshev(kDensitySpectralRadius);
    // With a body that sinks inside the solve its iteration is no longer the water's alone, and
    // weights made for the water's spectral radius overshoot the body's response to the film it
    // closes against the floor: the 10ρ cube of samples/buoyancy.json landed at 1.2 m/s and
    // bounced up at 1.9–2.8 m/s, turning over; with plain Jacobi iterates it bounced at
    // 0.19 m/s and settled flat (docs/VALIDATION.md "Bodies with DFSPH"). Light bodies (the
    // bubbles, a floating cylinder) keep the acceleration: they rise away from walls.
    const bool accelerate = !bodies_.holdsSinkingBody();
    double lowest = std::numeric_limits<double>::infinity();
    Outcome outcome;
    for (;;) {
        const Residual residual =
            solve == Solve::Divergence
                ? Residual{divergenceResiduals(), 0.0}
                : densityResiduals(dt, densities, accelerate ? chebyshev.next() : 1.0f);
        outcome.averageResidual = residual.error;
        const bool done = residual.error <= tolerance &&
                          residual.overshoot <= kOvershootAllowance * tolerance &&
                          outcome.iterations >= settings_.minIterations;
        if (done)
            return outcome;
        if (outcome.iterations >= settings_.maxIterations) {
            outcome.converged = false;
            return outcome;
        }
        const double residualSum = residual.error + residual.overshoot;
        if (residualSum > kChebyshevRestartGrowth * lowest)
            chebyshev.restart();
        lowest = std::min(lowest, residualSum);
        applyStiffness(stiffness_, &total);
        moveBodies(solve, dt);
        ++outcome.iterations;
    }
}

void DfsphSolver::moveBodies(Solve solve, float dt) {
    if (!bodies_.active())
        return;
    if (solve == Solve::Divergence)
        bodies_.update(divergenceTotal_, nullptr, Vec3d::Zero(), boundaryRate_);
    else
        bodies_.update(densityTotal_, &divergenceTotal_, double(dt) * settings_.gravity,
                       boundaryRate_);
}

void DfsphSolver::solveDivergence(double lastTimeStep, StepReport& report) {
    // The error is a rate; over the step about to be taken it is a compression, which is what
    // the tolerance bounds. Before the first step the longest step is the strictest guess.
    const double dt = lastTimeStep > 0.0 ? lastTimeStep : settings_.maxTimeStep;
    const double tolerance = settings_.divergenceErrorTarget * settings_.restDensity / dt;
    const Outcome outcome =
        iterate(Solve::Divergence, static_cast<float>(dt), tolerance, divergenceTotal_, nullptr);
    report.divergenceIterations = outcome.iterations;
    // The speed the step must resolve: the one gravity leads to over it (XSPH only averages).
    const Vec3f gravityStep = static_cast<float>(dt) * settings_.gravity.cast<float>();
    const Fastest fastest = findFastest(velocities_.size(), [&](std::size_t i) {
        return (velocities_[i].head<3>() + gravityStep).norm();
    });
    report.maxSpeed = fastest.speed;
    if (fastest.particle < velocities_.size())
        report.fastestAt = sortedPositions_[fastest.particle];
}

void DfsphSolver::applyNonPressureForces(const ParticleSet& fluid, float dt) {
    const Vec3f gravity = settings_.gravity.cast<float>();
    const float water = static_cast<float>(settings_.xsphFactor) * mass_;
    const float walls = static_cast<float>(settings_.wallXsphFactor / settings_.restDensity);
    std::copy(velocities_.begin(), velocities_.end(), unsmoothed_.begin());
    parallelFor(Range(0, velocities_.size(), kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            const Vec4f vi4 = unsmoothed_[i];
            const Vec3f vi = vi4.head<3>();
            const Vec4f towardWater = smoothingTowardWater(fluid, i, vi4);
            Vec3f towardWalls = Vec3f::Zero();
            Vec3f support = Vec3f::Zero();
            forEachBoundaryNeighbor(
                boundary_, kernel_.supportRadius(), i, sortedPositions_[i],
                [&](const BoundaryLayer& layer, std::uint32_t b, const Vec3f& d, float r2) {
                    if (walls > 0.0f)
                        towardWalls += wallSmoothing(vi, layer, b, r2);
                    if (interior_[i])
                        support += wallHydrostatic(layer, b, d, r2);
                });
            velocities_[i] =
                vi4 + water * towardWater + padded(walls * towardWalls + dt * (gravity + support));
        }
    });
}

Vec4f DfsphSolver::smoothingTowardWater(const ParticleSet& fluid, std::size_t i,
                                        const Vec4f& vi) const {
    // The kernel's values a chunk at a time (four at once on SSE2), then the sum in pair order.
    constexpr std::uint32_t kChunk = 64;
    std::array<float, kChunk + 3> distance2;
    std::array<float, kChunk + 3> weights;
    const Vec3f xi = sortedPositions_[i];
    const std::uint32_t* list = neighbors_.neighbors(i);
    const std::uint32_t count = neighbors_.count(i);
    Vec4f sum = Vec4f::Zero();
    for (std::uint32_t start = 0; start < count; start += kChunk) {
        const std::uint32_t size = std::min(kChunk, count - start);
        for (std::uint32_t k = 0; k < size; ++k)
            distance2[k] = (xi - sortedPositions_[list[start + k]]).squaredNorm();
        std::fill(distance2.begin() + size, distance2.begin() + size + 3, 0.0f);
        kernel_.valuesOfSquared(distance2.data(), size, weights.data());
        for (std::uint32_t k = 0; k < size; ++k) {
            const std::uint32_t j = list[start + k];
            sum += (unsmoothed_[j] - vi) * (weights[k] / fluid.densities[j]);
        }
    }
    return sum;
}

Vec3f DfsphSolver::wallHydrostatic(const BoundaryLayer& layer, std::uint32_t b, const Vec3f& d,
                                   float r2) const {
    // The wall's pressure is the particle's, solved for, plus the weight of the water between
    // them, ρ₀ g·(x_b − xᵢ) (Adami et al. 2012, as WCSPH's walls): without it the water next to a
    // side wall lacks the hydrostatic gradient its missing neighbours would give, and slides
    // down the wall.
    const float weight =
        -settings_.gravity.cast<float>().dot(d) / static_cast<float>(settings_.restDensity);
    return (-layer.psi()[b] * weight) * kernel_.gradientFromSquared(d, r2);
}

Vec3f DfsphSolver::wallSmoothing(const Vec3f& vi, const BoundaryLayer& layer, std::uint32_t b,
                                 float r2) const {
    return (layer.psi()[b] * kernel_.value(std::sqrt(r2))) * (layer.velocities()[b] - vi);
}

double DfsphSolver::fastestBodySpeed() const {
    const BoundaryLayer& layer = boundary_.movingLayer();
    double fastest = 0.0;
    for (std::size_t b = 0; b < layer.size(); ++b)
        if (const BodyContactTerms& terms = boundary_.contactTerms(layer.bodyOf()[b]);
            terms.dynamic && !terms.bubble)
            fastest = std::max(fastest, double(layer.velocities()[b].norm()));
    return fastest;
}

double DfsphSolver::flowTimeStep(double maxSpeed) const {
    if (maxSpeed <= 0.0)
        return settings_.maxTimeStep;
    return std::min(settings_.maxTimeStep,
                    settings_.flowCflFactor * settings_.particleSpacing / maxSpeed);
}

void DfsphSolver::chooseTimeStep(double, double timeToFrameEnd, StepReport& report) const {
    double dt = flowTimeStep(report.maxSpeed);
    const double bodySpeed = fastestBodySpeed();
    if (bodySpeed > 0.0)
        dt = std::min(dt, kBodyCflFactor * settings_.particleSpacing / bodySpeed);
    report.stepAtMinimum = dt < settings_.minTimeStep;
    dt = std::max(dt, settings_.minTimeStep);
    report.timeStep = landOnFrame(dt, timeToFrameEnd);
}

void DfsphSolver::computeDensities(ParticleSet& fluid, std::uint64_t, double dt,
                                   StepReport& report) {
    const float step = static_cast<float>(dt);
    applyNonPressureForces(fluid, step);
    parallelFor(Range(0, velocities_.size(), kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i)
            densityTotal_[i] *= step; // κ carried over → q for this step
    });
    const double tolerance = settings_.densityErrorTarget * settings_.restDensity;
    const Outcome outcome =
        iterate(Solve::Density, step, tolerance, densityTotal_, fluid.densities.data());
    report.densityIterations = outcome.iterations;
    report.densityError = outcome.averageResidual / settings_.restDensity;
    report.densityConverged = outcome.converged;
}

void DfsphSolver::computeForces(const ParticleSet&, double dt, StepReport&) {
    const std::size_t n = velocities_.size();
    const bool recordContacts = boundary_.hasDynamicBodies();
    if (recordContacts)
        contacts_.resize(n);
    const float step = static_cast<float>(dt);
    parallelFor(Range(0, n, kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            BoundaryContact::Nearest nearest;
            Vec3f impulse = Vec3f::Zero();
            if (nearestBoundary_[i] >= 0) {
                nearest.layer =
                    nearestIsMoving_[i] ? &boundary_.movingLayer() : &boundary_.staticLayer();
                nearest.boundaryParticle = nearestBoundary_[i];
                // The solved velocity is the one the particle moves with: no acceleration left.
                impulse = contact_.impulse(velocities_[i].head<3>(), Vec3f::Zero(), nearest,
                                           boundary_, step);
                velocities_[i] += padded(impulse / mass_);
            }
            if (recordContacts)
                BoundaryContact::record(i, nearest, impulse, boundary_, contacts_);
        }
    });
}

void DfsphSolver::computeBodyReactions(const ParticleSet&, double dt) {
    const BoundaryLayer& layer = boundary_.movingLayer();
    reactions_.assign(layer.size(), Vec3d::Zero());
    const float inverseStep = static_cast<float>(1.0 / dt);
    const float walls = static_cast<float>(settings_.wallXsphFactor / settings_.restDensity);
    parallelFor(Range(0, layer.size(), kSolveGrain), [&](const Range& r) {
        for (std::size_t b = r.begin(); b != r.end(); ++b) {
            if (!boundary_.contactTerms(layer.bodyOf()[b]).dynamic)
                continue;
            const Vec3f xb = layer.positions()[b];
            const float psi = layer.psi()[b];
            Vec3f force = Vec3f::Zero();
            for (std::uint32_t i : boundary_.movingPairs().waterNear(b)) {
                const Vec3f d = sortedPositions_[i] - xb;
                const float r2 = d.squaredNorm();
                if (r2 >= radius2_)
                    continue;
                // Both solves pushed water particle i off b by −qᵢ Ψ_b ∇W_ib; b takes the
                // opposite momentum over the step.
                const float stiffness = divergenceTotal_[i] + densityTotal_[i];
                force += (kWallPressureShare * mass_ * psi * stiffness * inverseStep) *
                         kernel_.gradientFromSquared(d, r2);
                force -= (mass_ * walls * inverseStep) *
                         wallSmoothing(unsmoothed_[i].head<3>(), layer,
                                       static_cast<std::uint32_t>(b), r2);
                if (interior_[i])
                    force -= mass_ * wallHydrostatic(layer, static_cast<std::uint32_t>(b), d, r2);
                if (contacts_.boundaryParticle[i] == static_cast<std::int32_t>(b))
                    force -= inverseStep * contacts_.impulse[i];
            }
            reactions_[b] = force.cast<double>();
        }
    });
}

bool DfsphSolver::integrate(ParticleSet& fluid, double dt) {
    const float step = static_cast<float>(dt);
    const float inverseStep = 1.0f / step;
    const std::size_t n = fluid.size();
    lastTimeStep_ = dt;
    std::atomic<bool> nonFinite{false};
    parallelFor(Range(0, n, kSolveGrain), [&](const Range& r) {
        for (std::size_t i = r.begin(); i != r.end(); ++i) {
            fluid.velocities[i] = velocities_[i].head<3>();
            fluid.positions[i] += step * fluid.velocities[i];
            // The totals stay as the next step's warm start, the density solve's as κ = q / Δt.
            densityTotal_[i] *= inverseStep;
            if (!fluid.positions[i].allFinite() || !fluid.velocities[i].allFinite())
                nonFinite.store(true, std::memory_order_relaxed);
        }
    });
    return nonFinite.load();
}

PressureWarmStart DfsphSolver::warmStart() const {
    return PressureWarmStart{divergenceTotal_, densityTotal_};
}

void DfsphSolver::restoreWarmStart(const PressureWarmStart& warmStart) {
    divergenceTotal_ = warmStart.divergence;
    densityTotal_ = warmStart.density;
}

float DfsphSolver::pressure(const ParticleSet& fluid, std::size_t i) const {
    if (i >= densityTotal_.size() || i >= divergenceTotal_.size())
        return 0.0f;
    const float rho = fluid.densities[i];
    float kappa = densityTotal_[i];
    if (lastTimeStep_ > 0.0)
        kappa += divergenceTotal_[i] / static_cast<float>(lastTimeStep_);
    return kappa * rho * rho;
}

std::size_t DfsphSolver::allocatedBytes() const {
    const auto bytes = [](const auto& v) { return v.capacity() * sizeof(v[0]); };
    return grid_.allocatedBytes() + boundary_.allocatedBytes() + sortedPositions_.allocatedBytes() +
           bytes(sortIds_) + neighbors_.allocatedBytes() + bytes(packedPositions_) +
           bytes(velocities_) + bytes(unsmoothed_) + bytes(factors_) + bytes(interior_) +
           bytes(boundaryGradient_) + bytes(boundaryRate_) + bytes(stiffness_) +
           bytes(divergenceTotal_) + bytes(densityTotal_) + bytes(previousDensityTotal_) +
           bytes(nearestBoundary_) + bytes(nearestIsMoving_) + contacts_.allocatedBytes() +
           bytes(reactions_) + bodies_.allocatedBytes();
}

} // namespace airtrap
