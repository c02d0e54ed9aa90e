#pragma once
// Divergence-free SPH (Bender & Koschier 2015, 2017; docs/METHOD.md "Water: divergence-free
// SPH"): densities by summation over water and boundary particles, a divergence solve that makes
// the velocity field free of compression, a step limited only by the flow's CFL, non-pressure
// forces (gravity, XSPH viscosity), and a density solve that removes the
// compression the step would leave. Both solves are Jacobi iterations on a per-particle
// stiffness, warm-started from the previous step's. Boundary particles (Akinci volumes) take part
// in both; the pressure they exert goes to their body, and the contact impulse of the
// impulse-based boundary force (eq. 4) stays for water approaching a body.
#include "scene/Scene.h"
#include "sph/BodySolveCoupling.h"
#include "sph/BoundaryContact.h"
#include "sph/NeighborList.h"
#include "sph/NeighborSweep.h"
#include "sph/PressureSolver.h"

#include <cstdint>
#include <vector>

namespace airtrap {

class DfsphSolver final : public PressureSolver {
public:
    //! The water of `domain` with no boundary yet: placeBoundary() gives it the bodies.
    DfsphSolver(const SolverSettings& settings, const Aabb& domain);

    void sortByCell(ParticleSet& fluid, StepReport& report) override;
    void placeBoundary(const std::vector<RigidBody>& bodies, std::size_t firstBubble) override;
    void pairMovingBoundary() override;
    //! ρᵢ = Σⱼ mⱼWᵢⱼ + Σ_b Ψ_b W_ib and the factors αᵢ of both solves; the nearest body for the
    //! contact impulse; the warm start carried into this step's order.
    void prepareDensities(ParticleSet& fluid, StepReport& report) override;
    void solveDivergence(double lastTimeStep, StepReport& report) override;
    //! Δt = λ Δx / |v|max within [min_time_step, max_time_step], and short enough for the
    //! dynamic bodies other than bubbles too (kBodyCflFactor).
    void chooseTimeStep(double lastMaxAcceleration, double timeToFrameEnd,
                        StepReport& report) const override;
    //! The density solve on the velocities the non-pressure forces predict for `dt`.
    void computeDensities(ParticleSet& fluid, std::uint64_t step, double dt,
                          StepReport& report) override;
    //! The contact impulses of eq. 4 on the solved velocities.
    void computeForces(const ParticleSet& fluid, double dt, StepReport& report) override;
    void computeBodyReactions(const ParticleSet& fluid, double dt) override;
    const std::vector<Vec3d>& bodyReactions() const override { return reactions_; }
    //! v ← the solved velocity, x ← x + Δt v.
    bool integrate(ParticleSet& fluid, double dt) override;

    const CubicSplineKernel& kernel() const override { return kernel_; }
    float particleMass() const override { return mass_; }
    const BoundaryModel& boundary() const override { return boundary_; }
    const NeighborGrid& grid() const override { return grid_; }
    const PositionArrays& sortedPositions() const override { return sortedPositions_; }
    std::size_t allocatedBytes() const override;
    //! pᵢ = ρᵢ² (q_div + q_dens) / Δt: the pressure both solves of the last step exerted.
    float pressure(const ParticleSet& fluid, std::size_t i) const override;
    //! The totals of both solves' stiffness at the end of the last step (κ for the density).
    PressureWarmStart warmStart() const override;
    void restoreWarmStart(const PressureWarmStart& warmStart) override;

private:
    enum class Solve { Divergence, Density };
    struct Outcome {
        int iterations = 0;
        double averageResidual = 0.0; //!< of the last residual pass
        bool converged = true;
    };
    //! The averages a residual pass leaves, kg/m³ (or kg/m³/s for the divergence solve).
    struct Residual {
        double error = 0.0;     //!< compression left: what the solve's target bounds
        double overshoot = 0.0; //!< expansion where a stiffness still pushes
    };

    //! The sums over one water particle's water neighbours that prepareParticle() needs.
    struct WaterSums {
        float weights = 0.0f;              //!< Σⱼ Wᵢⱼ, W(0) included
        Vec3f gradientSum = Vec3f::Zero(); //!< Σⱼ ∇Wᵢⱼ from the stored codes
        float gradientSquares = 0.0f;      //!< Σⱼ |∇Wᵢⱼ|²
        std::uint32_t count = 0;           //!< neighbours
    };

    //! Sweeps water particle i's neighbours once: density, α, boundary sums, nearest body.
    void prepareParticle(ParticleSet& fluid, std::size_t i, NeighborList::Sink& sink);
    //! Adds the pairs of one batch of the sweep (i itself skipped) to `sums` and to the list
    //! (docs/PERFORMANCE.md "Latency taken out of the pair loops").
    void addWaterPairs(std::size_t i, const std::uint32_t* batch, std::size_t size, WaterSums& sums,
                       NeighborList::Sink& sink) const;
    //! Iterates `solve` until its average residual is at most `tolerance` (kg/m³, per second for
    //! the divergence), starting from the stiffness already in `total`.
    //! `densities` (kg/m³) are the step's, for the density solve.
    Outcome iterate(Solve solve, float dt, double tolerance, std::vector<float>& total,
                    const float* densities);
    //! stiffness_[i] ← Dρᵢ/Dt for every particle (or only the interior ones, 0 elsewhere). A pass
    //! of its own: with the residual's arithmetic after each particle's sum, that arithmetic's
    //! latency (a horizontal sum, a division) held up the next particle's pairs: 10 % of a step's
    //! profile, 4 % in a pass of its own (docs/PERFORMANCE.md).
    void storeDensityRates(bool interiorOnly);
    //! Each interior particle's compression rate and the stiffness increment that removes it
    //! (into stiffness_); returns the average compression rate.
    double divergenceResiduals();
    //! Each particle's compression over the step and the change of its stiffness (into
    //! stiffness_): the relaxed Jacobi iterate, accelerated by `chebyshevWeight` and kept at or
    //! above zero. Returns the average compression and overshoot.
    Residual densityResiduals(float dt, const float* densities, float chebyshevWeight);
    //! The step the flow alone allows: λ Δx / |v|max within max_time_step.
    double flowTimeStep(double maxSpeed) const;
    //! The largest speed (m/s) of a dynamic body's boundary particle at the step's start,
    //! bubbles left out.
    double fastestBodySpeed() const;
    //! The dynamic bodies' velocities after the stiffness applied so far in `solve`
    //! (BodySolveCoupling).
    void moveBodies(Solve solve, float dt);
    //! Dρᵢ/Dt of the current velocities over water and boundary particles.
    float densityRate(std::size_t i) const;
    //! vᵢ ← vᵢ − Σⱼ m(qᵢ + qⱼ)∇Wᵢⱼ − 2qᵢ Bᵢ (the mirrored wall) for the stiffness q in `stiffness`,
    //! and total += q.
    void applyStiffness(const std::vector<float>& stiffness, std::vector<float>* total);
    //! v ← v + Δt g and XSPH smoothing toward the water's and the walls' velocities
    //! (solver.xsph, solver.wall_xsph); the velocities before it are kept in unsmoothed_.
    void applyNonPressureForces(const ParticleSet& fluid, float dt);
    //! The previous step's stiffness values, carried into this step's sorted order.
    void carryWarmStart(std::size_t n);
    //! Ψ_b W_ib (v_b − vᵢ): boundary particle b's share of the walls' XSPH for velocity vi.
    Vec3f wallSmoothing(const Vec3f& vi, const BoundaryLayer& layer, std::uint32_t b,
                        float r2) const;
    //! Σⱼ W_ij (vⱼ − vᵢ) / ρⱼ over water particle i's neighbours, on the velocities before the
    //! non-pressure forces: the water's XSPH sum (without its factor m).
    Vec4f smoothingTowardWater(const ParticleSet& fluid, std::size_t i, const Vec4f& vi) const;
    //! The acceleration of water particle i from the hydrostatic part of boundary particle b's
    //! pressure, d = xᵢ − x_b.
    Vec3f wallHydrostatic(const BoundaryLayer& layer, std::uint32_t b, const Vec3f& d,
                          float r2) const;
    //! Σⱼ term(j, ∇ᵢWᵢⱼ as xyz0) over water particle i's neighbours, from the factors' codes
    //! stored with the list. `term` must be linear in the gradient.
    template <class Term>
    Vec4f sumOverWaterGradients(std::size_t i, Term&& term) const;

    SolverSettings settings_;
    CubicSplineKernel kernel_;
    float spacing_;
    float mass_;
    float radius2_;
    float contactRadius_;
    Aabb gridDomain_;
    BoundaryModel boundary_;
    NeighborGrid grid_;
    BoundaryContact contact_;

    // Per particle, in the sorted order of the current step.
    PositionArrays sortedPositions_;
    std::vector<std::uint32_t> sortIds_; //!< the ids' spare for sortByCell()
    //! With each pair's dW/dr / r as a 16-bit code, so that the solves' passes need no kernel
    //! evaluation: they run 2.1 times faster for 2 bytes per pair (docs/PERFORMANCE.md).
    NeighborList neighbors_;
    //! The positions again as xyz0, so that the solves' passes load each neighbour's in one
    //! aligned read and work on all three components at once (docs/PERFORMANCE.md).
    std::vector<Vec4f> packedPositions_;
    std::vector<Vec4f> velocities_; //!< xyz0, solved in place, written back by integrate()
    std::vector<Vec4f> unsmoothed_; //!< xyz0, before the non-pressure forces
    std::vector<float> factors_; //!< αᵢ = 1 / (|Σⱼ m∇Wᵢⱼ + Bᵢ|² + Σⱼ |m∇Wᵢⱼ|²)
    std::vector<std::uint8_t> interior_;  //!< enough neighbours for the divergence solve
    std::vector<Vec3f> boundaryGradient_; //!< Bᵢ = Σ_b Ψ_b ∇W_ib
    std::vector<float> boundaryRate_;     //!< Σ_b Ψ_b v_b·∇W_ib
    std::vector<float> stiffness_;        //!< this iteration's increment
    //! q of the divergence solve, summed; between steps the next one's warm start, in the
    //! water's order at the end of the last step.
    std::vector<float> divergenceTotal_;
    //! q of the density solve, summed; between steps κ = q / Δt, the next one's warm start.
    std::vector<float> densityTotal_;
    std::vector<float> previousDensityTotal_;   //!< the iterate before, for Chebyshev's weights
    std::vector<std::int32_t> nearestBoundary_; //!< within the contact radius, −1 for none
    std::vector<std::uint8_t> nearestIsMoving_; //!< in the moving layer rather than the static
    ContactRecords contacts_;
    BodySolveCoupling bodies_;
    std::vector<Vec3d> reactions_;
    double lastTimeStep_ = 0.0; //!< 0 until a step is taken (also after a resume)
};

} // namespace airtrap
