#pragma once
// Weakly compressible SPH (paper §3.1, docs/METHOD.md "Water: weakly compressible SPH" and
// "Impulse-based boundary force"): continuity density (eq. 2) with a periodic Shepard
// re-initialisation, Tait equation of state (eq. 3, γ = 7, c = 10·u_max), Monaghan momentum with
// artificial viscosity (eq. 1), boundary particles for every rigid body, and the contact impulse of
// the impulse-based boundary force (eq. 4) for water approaching a body.
#include "scene/Scene.h"
#include "sph/InteractionPass.h"
#include "sph/PressureSolver.h"
#include "sph/TaitEquationOfState.h"

#include <cstdint>
#include <vector>

namespace airtrap {

class WcsphSolver final : public PressureSolver {
public:
    //! The water of `domain` with no boundary yet: placeBoundary() gives it the bodies.
    WcsphSolver(const SolverSettings& settings, const Aabb& domain);

    void sortByCell(ParticleSet& fluid, StepReport& report) override;
    void placeBoundary(const std::vector<RigidBody>& bodies, std::size_t firstBubble) override;
    void pairMovingBoundary() override;
    //! Nothing: the densities come from the continuity equation in computeDensities().
    void prepareDensities(ParticleSet&, StepReport&) override {}
    //! Nothing: a weakly compressible fluid corrects its divergence through its pressure.
    void solveDivergence(double, StepReport&) override {}
    //! From the CFL condition on the speed of sound and the last step's largest acceleration.
    void chooseTimeStep(double lastMaxAcceleration, double timeToFrameEnd,
                        StepReport& report) const override;
    //! Every shepard_interval steps the Shepard re-initialisation; then ρ advanced by the
    //! continuity equation (eq. 2) and the pressures of the equation of state (eq. 3).
    void computeDensities(ParticleSet& fluid, std::uint64_t step, double dt,
                          StepReport& report) override;
    //! The momentum equation (eq. 1) with the boundary force's contact impulses (eq. 4).
    void computeForces(const ParticleSet& fluid, double dt, StepReport& report) override;
    void computeBodyReactions(const ParticleSet& fluid, double dt) override;
    const std::vector<Vec3d>& bodyReactions() const override { return reactions_; }
    //! Symplectic Euler: v ← v + Δt a, x ← x + Δt v.
    bool integrate(ParticleSet& fluid, double dt) override;

    const CubicSplineKernel& kernel() const override { return kernel_; }
    float particleMass() const override { return mass_; }
    const BoundaryModel& boundary() const override { return boundary_; }
    const NeighborGrid& grid() const override { return grid_; }
    const PositionArrays& sortedPositions() const override { return sortedPositions_; }
    std::size_t allocatedBytes() const override;
    //! From the equation of state (eq. 3).
    float pressure(const ParticleSet& fluid, std::size_t i) const override {
        return equationOfState_.pressure(fluid.densities[i]);
    }
    PressureWarmStart warmStart() const override { return {}; }
    void restoreWarmStart(const PressureWarmStart&) override {}

    const TaitEquationOfState& equationOfState() const { return equationOfState_; }

private:
    //! Re-initialises every density by Shepard interpolation, on this step's sorted particles.
    void shepardFilter(ParticleSet& fluid);
    //! ρ ← max(ρ₀, ρ + Δt dρ/dt) and the pressure terms p/ρ²; returns max |ρ/ρ₀ − 1|.
    double advanceDensities(ParticleSet& fluid, double dt);
    InteractionConstants interactionConstants() const;
    //! What the interaction passes read: the water, its sorted positions, the grid, the bodies.
    InteractionInputs inputs(const ParticleSet& fluid) const;

    SolverSettings settings_;
    CubicSplineKernel kernel_;
    float spacing_;
    float mass_;
    TaitEquationOfState equationOfState_;
    Aabb gridDomain_;
    BoundaryModel boundary_;
    NeighborGrid grid_;
    InteractionPass passes_;

    // Per-particle scratch, in the sorted order of the current step.
    PositionArrays sortedPositions_;
    NeighborList neighbors_;
    std::vector<float> pressureOverDensity2_; //!< p/ρ², the pressure term of eq. 1
    std::vector<float> densityRates_;         //!< dρ/dt (eq. 2)
    std::vector<Vec3f> accelerations_;        //!< dv/dt (eq. 1 + contact impulses)
    std::vector<std::uint32_t> sortIds_;      //!< the ids' spare for sortByCell()
    ContactRecords contacts_;                 //!< impulses from dynamic bodies, for their reaction
    std::vector<Vec3d> reactions_;            //!< N, the water's force on each boundary particle
};

} // namespace airtrap
