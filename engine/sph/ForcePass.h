#pragma once
// The one neighbour pass of a step: for every water particle the density rate (eq. 2) and the
// acceleration (eq. 1 with Monaghan's artificial viscosity, gravity, and the impulse-based
// boundary force of eq. 4 against every body). Each particle sums only into its own outputs, so
// the pass is parallel without atomics and gives the same bits on any number of threads.
#include "sph/BoundaryModel.h"
#include "sph/CubicSplineKernel.h"
#include "sph/NeighborGrid.h"
#include "sph/ParticleSet.h"

#include <vector>

namespace airtrap {

//! Constants of the pass, derived once from the solver settings.
struct ForceConstants {
    float mass = 0.0f;           //!< water particle mass, kg
    float fluidViscosity = 0.0f; //!< α c h of Π between water particles
    float wallViscosity = 0.0f;  //!< the same against boundary particles (wall friction)
    float contactRadius = 0.0f;  //!< m, distance below which the contact impulse may act
    float restitution = 0.0f;    //!< ε of the contact impulse against bodies
    Vec3f gravity = Vec3f::Zero();
};

//! Positions as three separate arrays, so that the distance test over a row of candidates
//! streams one float per coordinate.
struct PositionArrays {
    std::vector<float> x, y, z;
    void resize(std::size_t n) {
        x.resize(n);
        y.resize(n);
        z.resize(n);
    }
};

class ForcePass {
public:
    ForcePass(const CubicSplineKernel& kernel, const ForceConstants& constants);

    //! Fills `densityRates` and `accelerations` (sized by the caller) for the sorted particles
    //! and returns the largest acceleration without contact impulses (for the next Δt).
    double run(const ParticleSet& fluid, const PositionArrays& sortedPositions,
               const std::vector<float>& pressureOverDensity2, const NeighborGrid& grid,
               const BoundaryModel& boundary, double dt, std::vector<float>& densityRates,
               std::vector<Vec3f>& accelerations) const;

private:
    struct Inputs;
    //! The nearest boundary particle within the contact radius, if any.
    struct Contact {
        std::int64_t boundaryParticle = -1;
        float distance2 = 0.0f;
    };

    //! Adds Σⱼ mⱼ-free pressure and viscosity terms to `force`; returns dρ/dt from the water.
    float fluidTerms(std::size_t i, const Inputs& in, Vec3f& force) const;
    //! Adds F_f/mᵢ of every body to `acceleration`; returns dρ/dt from the boundary particles.
    float boundaryTerms(std::size_t i, const Inputs& in, Vec3f& acceleration,
                        Contact& contact) const;
    //! J/(mᵢΔt) of eq. 4 for a particle that would still approach the body after this step. A
    //! static body has infinite mass, so j = −(1 + ε) mᵢ uₙ.
    Vec3f contactImpulse(const Vec3f& velocity, const Vec3f& acceleration, const Contact& contact,
                         const BoundaryModel& boundary, float dt) const;

    CubicSplineKernel kernel_;
    ForceConstants constants_;
    float radius2_;
    float eta2_;
};

} // namespace airtrap
