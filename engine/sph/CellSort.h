#pragma once
// The first phase of every step, the same for both pressure solvers: the water sorted by cell
// onto the neighbour grid, so that neighbours sit close in memory.
#include "sph/NeighborGrid.h"
#include "sph/NeighborSweep.h"
#include "sph/ParticleSet.h"
#include "sph/StepReport.h"

namespace airtrap {

//! Builds `grid` for the water's positions and reorders `fluid` by cell, dropping the particles
//! outside the domain (counted in report.removedParticles); `sorted` gets the positions as three
//! arrays, `scratch` is reused storage. Reports the largest speed, found in the same sweep.
void sortByCell(NeighborGrid& grid, ParticleSet& fluid, ParticleSet& scratch,
                PositionArrays& sorted, StepReport& report);

} // namespace airtrap
