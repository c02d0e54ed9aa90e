#pragma once
// The dynamic bodies moved inside a divergence-free pressure solve (docs/METHOD.md "Bodies inside
// the solve"). A solve that treats a body as a wall moving at its old velocity pushes the water
// as if the body were infinitely heavy: a light body then takes the whole reaction of the water
// it would have had to push, one step late, and its motion grows without bound (the added-mass
// instability of partitioned coupling, Förster, Wall & Ramm 2007); a heavy body closing a thin
// film squeezes the water out at any speed and bounces off it. Here each iteration of the solve
// also moves the bodies: from the stiffness the water has been given so far, the impulse each
// body took from it (the opposite of the water's), and from that the velocity the body would end
// the step with, which the walls then move with in the next iteration's compression. The idea is
// Gissler et al.'s ("Interlinked SPH Pressure Solvers for Strong Fluid-Rigid Coupling", ACM TOG
// 2019): the bodies' response inside the solve; the body update here is a fixed-point iteration
// rather than their boundary pressure solve, relaxed by Aitken's Δ² method as partitioned
// fluid-structure solvers do (Küttler & Wall 2008): the water a body must push (its added mass)
// varies from half its volume's worth in open water to many times that in a film closing
// against a wall, and a fixed relaxation that suits one overshoots the other.
#include "core/Math.h"
#include "sph/BoundaryModel.h"
#include "sph/CubicSplineKernel.h"
#include "sph/NeighborSweep.h"

#include <cstdint>
#include <vector>

namespace airtrap {

class BodySolveCoupling {
public:
    //! `particleMass` (kg) of a water particle; `restDensity` (kg/m³) sets the bodies' added
    //! mass; a water particle's stiffness q pushes it off a boundary particle by
    //! −`wallShare` q Ψ_b ∇W_ib.
    BodySolveCoupling(const CubicSplineKernel& kernel, float particleMass, float restDensity,
                      float wallShare);

    //! Takes the dynamic bodies of `boundary` at their velocities at the step's start, and the
    //! water near them (sorted positions `water`), whose `boundaryRate` (Σ_b Ψ_b v_b·∇W_ib) holds
    //! those velocities' share.
    void begin(const BoundaryModel& boundary, const PositionArrays& water,
               const std::vector<float>& boundaryRate);
    bool active() const { return !bodies_.empty(); }
    //! Whether a dynamic body at least as dense as the water is among them: one that can sink
    //! onto the floor or another body and close a film of water against it.
    bool holdsSinkingBody() const { return holdsSinkingBody_; }
    //! The water particles with a dynamic body's boundary particle within reach.
    const std::vector<std::uint32_t>& nearWater() const { return nearWater_; }
    //! Forgets the relaxation's history: a new solve's iterates start.
    void startSolve();

    //! One iteration's update: each body's velocity moved toward the one the stiffness the water
    //! has been given (`applied`, plus `alsoApplied` if not null) and `drift` (m/s: Δt g in the
    //! density solve, 0 in the divergence solve) would leave it with; `boundaryRate` rewritten
    //! for the water near the bodies with those velocities.
    void update(const std::vector<float>& applied, const std::vector<float>* alsoApplied,
                const Vec3d& drift, std::vector<float>& boundaryRate);

    std::size_t allocatedBytes() const;

private:
    struct Motion {
        std::uint32_t body = 0; //!< index into the boundary's bodies
        Vec3d centre = Vec3d::Zero();
        Vec3d startVelocity = Vec3d::Zero();
        Vec3d startSpin = Vec3d::Zero();
        Vec3d velocity = Vec3d::Zero(); //!< the iterate, m/s
        Vec3d spin = Vec3d::Zero();     //!< rad/s
        double mass = 0.0;
        Mat3d inverseInertia = Mat3d::Zero();
        double initialRelaxation = 1.0; //!< m / (m + mₐ), mₐ estimated
        double relaxation = 1.0;
        double spinRelaxation = 1.0;
        //! The last update's target minus iterate; empty history after startSolve().
        Vec3d residual = Vec3d::Zero();
        Vec3d spinResidual = Vec3d::Zero();
        bool hasResidual = false;
    };

    //! Aitken's Δ² update of a relaxation factor from two successive residuals.
    static double aitken(double relaxation, const Vec3d& previous, const Vec3d& current);

    //! The impulse the water near each of the moving layer's particles gave it, for `stiffness`.
    void layerImpulses(const std::vector<float>& applied, const std::vector<float>* alsoApplied);
    //! Σ_b Ψ_b v_b·∇W_ib over water particle i's partners among the dynamic bodies, at the
    //! iterated velocities.
    float dynamicRate(std::size_t i) const;
    Vec3f layerVelocity(std::uint32_t b) const;

    const CubicSplineKernel& kernel_;
    float particleMass_;
    float restDensity_;
    float wallShare_;
    const BoundaryModel* boundary_ = nullptr;
    const PositionArrays* water_ = nullptr;
    std::vector<Motion> bodies_;
    std::vector<std::int32_t> motionOf_;   //!< per body of the boundary; −1 if not dynamic
    std::vector<std::uint32_t> nearWater_; //!< water particles with a dynamic partner
    std::vector<float> otherRate_;         //!< their rate from everything but those partners
    std::vector<Vec3f> impulses_;          //!< per moving-layer particle, N·s
    bool holdsSinkingBody_ = false;
};

} // namespace airtrap
