#pragma once
// The two neighbour passes of a step. Each particle sums only into its own outputs, so both are
// parallel without atomics and give the same bits on any number of threads.
//  1. densityRates: dρ/dt of eq. 2 over water and boundary particles.
//  2. accelerations: eq. 1 with Monaghan's artificial viscosity, gravity, and the impulse-based
//     boundary force of eq. 4 (fluid force F_f plus the contact impulse J/Δt) against every body.
// A third, bodyReactions, gives each dynamic body the equal and opposite force, summed per
// boundary particle over its water neighbours with the same pair formula as pass 2.
// Two passes rather than one because the pressure of pass 2 must come from the density already
// advanced with pass 1 (symplectic Euler for the pair ρ, v): with both evaluated from the same old
// state, the scheme is forward Euler for sound waves, which grow without bound.
#include "sph/BoundaryContact.h"
#include "sph/BoundaryModel.h"
#include "sph/ContactRecords.h"
#include "sph/CubicSplineKernel.h"
#include "sph/NeighborList.h"
#include "sph/NeighborSweep.h"
#include "sph/ParticleSet.h"

#include <vector>

namespace airtrap {

//! Constants of the passes, derived once from the solver settings.
struct InteractionConstants {
    float mass = 0.0f;           //!< water particle mass, kg
    float fluidViscosity = 0.0f; //!< α c h of Π between water particles
    float wallViscosity = 0.0f;  //!< the same against boundary particles (wall friction)
    float contactRadius = 0.0f;  //!< m, distance below which the contact impulse may act
    Vec3f gravity = Vec3f::Zero();
};

//! The sorted particle data both passes read.
struct InteractionInputs {
    const ParticleSet& fluid;
    const PositionArrays& positions;
    const NeighborGrid& grid;
    const BoundaryModel& boundary;
};

class InteractionPass {
public:
    InteractionPass(const CubicSplineKernel& kernel, const InteractionConstants& constants);

    //! dρ/dt of every particle into `rates` (sized by the caller); records each particle's water
    //! neighbours in `neighbors` for the force pass.
    void densityRates(const InteractionInputs& in, std::vector<float>& rates,
                      NeighborList& neighbors) const;

    //! dv/dt of every particle into `accelerations` (sized by the caller), from the pressure term
    //! p/ρ² of each particle. Returns the largest acceleration without contact impulses, which
    //! feeds the next Δt. When `contacts` is given (sized by the caller), records the impulses
    //! from dynamic bodies there.
    double accelerations(const InteractionInputs& in, const NeighborList& neighbors,
                         const std::vector<float>& pressureTerms, double dt,
                         std::vector<Vec3f>& accelerations, ContactRecords* contacts) const;

    //! The force (N, world) the water exerts on each boundary particle of a dynamic body this
    //! step, into `forces` (one per sorted particle of the moving layer; zero for kinematic
    //! bodies): minus the
    //! pressure and friction it exerts on its water neighbours, minus the contact impulses it
    //! gave them over Δt. Same inputs as the force pass, after it.
    void bodyReactions(const InteractionInputs& in, const std::vector<float>& pressureTerms,
                       const ContactRecords& contacts, double dt, std::vector<Vec3d>& forces) const;

private:
    float boundaryDensityRate(std::size_t i, const InteractionInputs& in) const;
    Vec3f waterForce(std::size_t i, const InteractionInputs& in, const NeighborList& neighbors,
                     const std::vector<float>& pressureTerms) const;
    Vec3f boundaryForce(std::size_t i, const InteractionInputs& in, float pressureTerm,
                        BoundaryContact::Nearest& contact) const;
    //! Acceleration of water particle i (at xi, velocity vi, density rhoi, pressure term p/ρ²)
    //! from boundary particle b at offset d = xi − x_b, |d|² = r2 < support²: the pressure of
    //! the particle and of the wall plus the wall's artificial viscosity, weighted by Ψ_b.
    Vec3f boundaryPairAcceleration(const Vec3f& xi, const Vec3f& vi, float rhoi, float pressureTerm,
                                   std::size_t b, const Vec3f& d, float r2,
                                   const BoundaryLayer& layer) const;
    CubicSplineKernel kernel_;
    InteractionConstants constants_;
    BoundaryContact contact_;
    float radius2_;
    float eta2_;
};

} // namespace airtrap
