#pragma once
// The water's part of a step, as Simulation::takeStep() drives it (docs/ARCHITECTURE.md,
// "The step"): the particles sorted onto the neighbour grid, the boundary particles of the rigid
// bodies, densities, pressures and forces, the time step they allow, and the move. The bodies,
// the bubbles and their contacts are not the solver's: the step moves them with the reactions
// the solver reports. WcsphSolver (the paper's weakly compressible SPH) and DfsphSolver
// (divergence-free SPH) implement it; a phase one of them does not have is empty there.
#include "rigid/RigidBody.h"
#include "sph/BoundaryModel.h"
#include "sph/CubicSplineKernel.h"
#include "sph/NeighborGrid.h"
#include "sph/ParticleSet.h"
#include "sph/PressureWarmStart.h"
#include "sph/StepReport.h"

#include <cstdint>
#include <vector>

namespace airtrap {

class PressureSolver {
public:
    virtual ~PressureSolver() = default;

    // The phases, in the order the step calls them. Each reads the water as the ones before it
    // left it.

    //! Sorts the particles by cell onto grid(), dropping those outside the domain; reports how
    //! many left and the largest speed (for Δt).
    virtual void sortByCell(ParticleSet& fluid, StepReport& report) = 0;
    //! Places the boundary particles of `bodies` at their current poses; those from index
    //! `firstBubble` on are bubbles'. Touches no water, so it may run beside sortByCell().
    virtual void placeBoundary(const std::vector<RigidBody>& bodies, std::size_t firstBubble) = 0;
    //! Finds the water near the moving bodies' boundary particles on this step's grid.
    virtual void pairMovingBoundary() = 0;
    //! DFSPH: the densities by summation and the factors of both solves, on this step's grid.
    virtual void prepareDensities(ParticleSet& fluid, StepReport& report) = 0;
    //! DFSPH: makes the velocity field divergence-free, then the non-pressure accelerations and
    //! the speed they lead to (report.maxSpeed). `lastTimeStep` (s; 0 before the first step)
    //! scales the solve's error.
    virtual void solveDivergence(double lastTimeStep, StepReport& report) = 0;
    //! report.timeStep, the step the water allows after report.maxSpeed, at most
    //! `timeToFrameEnd`, so a frame's end is met exactly.
    virtual void chooseTimeStep(double lastMaxAcceleration, double timeToFrameEnd,
                                StepReport& report) const = 0;
    //! The densities (and what the pressures need of them) for a step of `dt` s; `step` counts
    //! the steps since t = 0. DFSPH: the density solve.
    virtual void computeDensities(ParticleSet& fluid, std::uint64_t step, double dt,
                                  StepReport& report) = 0;
    //! Every particle's acceleration: pressure, viscosity, boundary forces and gravity. Only
    //! reads the water, so other readers of it may run beside.
    virtual void computeForces(const ParticleSet& fluid, double dt, StepReport& report) = 0;
    //! The water's force on each dynamic body's boundary particle, from this step's forces.
    virtual void computeBodyReactions(const ParticleSet& fluid, double dt) = 0;
    //! N, per sorted particle of boundary().movingLayer(), from computeBodyReactions().
    virtual const std::vector<Vec3d>& bodyReactions() const = 0;
    //! Moves the water over `dt` s; returns whether a NaN or infinity appeared. Touches no body,
    //! so the bodies may move beside it.
    virtual bool integrate(ParticleSet& fluid, double dt) = 0;

    // What the rest of the step reads of the water.

    virtual const CubicSplineKernel& kernel() const = 0;
    //! kg
    virtual float particleMass() const = 0;
    virtual const BoundaryModel& boundary() const = 0;
    virtual const NeighborGrid& grid() const = 0;
    //! The water's positions as the last step sorted them onto grid(), before it moved them.
    virtual const PositionArrays& sortedPositions() const = 0;
    //! Heap bytes held by the solver's grids and scratch arrays (not the particle state).
    virtual std::size_t allocatedBytes() const = 0;
    //! Pa, of particle i of the water as the last step left it.
    virtual float pressure(const ParticleSet& fluid, std::size_t i) const = 0;

    //! What the next step's solves start from, in the water's order (empty for WCSPH).
    virtual PressureWarmStart warmStart() const = 0;
    //! Continues from a cached state's warm start.
    virtual void restoreWarmStart(const PressureWarmStart& warmStart) = 0;
};

} // namespace airtrap
