#pragma once
// The forces a bubble feels beyond the impulse-based boundary force every body gets (paper
// §3.3, docs/METHOD.md "Forces" and "Bubble–bubble impulses"):
//  - the auxiliary buoyancy of eq. 5: a submerged bubble's vertical speed is steered toward the
//    surrounding water's plus the Stokes speed v_s = 2/9 g R²/ν, capped. The water's pressure
//    gives a light body its buoyancy by itself, but how fast a sphere a few particles across
//    rises through SPH water depends on the resolution; the steering replaces the step's
//    vertical change with a relaxation toward the target over the rise time τ, so the rise
//    meets the target whatever the resolution.
//  - the drag of eq. 6, F = −(μ + k)Δv against the water's velocity around it, with the Stokes
//    drag 6πρ₀νR for μ and k = drag rate × mass, integrated implicitly: explicit drag on a body
//    this light is unstable.
//  Both act on the immersed part only: they are scaled by the share of the bubble's surface in
//  water (BubbleImmersion's probes), so a bubble breaking the surface is no longer pulled up by
//  water that is not there, and one in the air feels neither.
//  - bubble–bubble impulses with non-positive restitution (BubblePairImpulse).
// The bubbles' bodies sit at the end of the rigid world's body list (sim/RigidWorld), from index
// `first` on.
#include "bubbles/BubbleBodyFactory.h"
#include "bubbles/BubblePairImpulse.h"
#include "bubbles/BubbleState.h"
#include "bubbles/BubbleSurroundings.h"
#include "sph/NeighborGrid.h"
#include "sph/NeighborSweep.h"
#include "sph/ParticleSet.h"

#include <array>
#include <vector>

namespace airtrap {

class BubbleDynamics {
public:
    BubbleDynamics(const BubbleSettings& bubbles, const SolverSettings& solver,
                   const CubicSplineKernel& kernel);

    //! Makes bodies[first…] the bodies of `bubbles`, in their order and states; bodies of
    //! bubbles already there are kept, so only new bubbles are sampled.
    void syncBodies(std::vector<RigidBody>& bodies, std::size_t first,
                    const std::vector<BubbleState>& bubbles);

    //! Simulated time (s) between two measures of a bubble's surroundings. The measure reads
    //! every water particle within two support radii of the bubble, several hundred per bubble,
    //! and was the largest part of the bubbles' cost when taken every step; what it measures
    //! changes slowly: in a quarter of a millisecond the water moves less than a tenth of a
    //! support radius at the speeds the samples reach, and an impact on a floating bubble lasts
    //! far longer. That is about five steps of the samples' WCSPH (50–60 µs each), as the rule
    //! counted before it counted time, and every step of DFSPH, whose steps are longer.
    static constexpr double kMeasureInterval = 0.00025;

    //! Whether the step [from, to) (s) has surroundings to measure: every bubble's when a
    //! multiple of kMeasureInterval falls in it, a new bubble's at its first step.
    static bool measureDue(double from, double to, const std::vector<BubbleState>& bubbles);
    //! Measures the water around the bubbles due in the step [from, to) from the step's sorted
    //! water, into their BubbleState::surroundings.
    void measureSurroundings(double from, double to, const std::vector<RigidBody>& bodies,
                             std::size_t first, std::vector<BubbleState>& bubbles,
                             const ParticleSet& fluid, const PositionArrays& positions,
                             const NeighborGrid& grid) const;

    //! Drag and steering, once the water's force and gravity have changed the bodies' velocities
    //! over a (sub-)step of `dt` s; `before` holds every body's linear velocity as that sub-step
    //! began, `bubbles` the bubbles' surroundings measured for the step.
    void applyForces(std::vector<RigidBody>& bodies, std::size_t first,
                     const std::vector<BubbleState>& bubbles, const std::vector<Vec3d>& before,
                     double dt) const;
    //! The impulses between touching bubbles.
    void applyPairImpulses(std::vector<RigidBody>& bodies, std::size_t first) const;

    //! m/s, the Stokes rise speed of a bubble of `radius` m (eq. 5), capped.
    double riseSpeed(double radius) const;

private:
    //! Whether the bodies from `first` on are those of `bubbles` already.
    bool sameBubbles(const std::vector<BubbleState>& bubbles) const;
    BubbleSurroundings measureOne(const RigidBody& body, double radius, const ParticleSet& fluid,
                                  const PositionArrays& positions, const NeighborGrid& grid) const;
    //! Marks the probes a water particle near the bubble wets and returns how fast it approaches
    //! the bubble's surface.
    double touchingWater(const RigidBody& body, double radius, const Vec3f& position,
                         const Vec3f& velocity, BubbleImmersion::WetProbes& wet) const;

    BubbleSettings settings_;
    double restDensity_;
    double spacing_;
    float support_;
    Vec3d gravity_;
    CubicSplineKernel kernel_;
    BubbleImmersion immersion_;
    BubbleBodyFactory factory_;
    BubblePairImpulse pairs_;
    std::vector<std::uint32_t> bodyIds_; //!< id of the bubble of each body from `first` on
    std::vector<double> radii_;
};

} // namespace airtrap
