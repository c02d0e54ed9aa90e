#pragma once
// The first phase of every step, the same for both pressure solvers: the water sorted by cell
// onto the neighbour grid, so that neighbours sit close in memory.
#include "sph/NeighborGrid.h"
#include "sph/NeighborSweep.h"
#include "sph/ParticleSet.h"
#include "sph/StepReport.h"

#include <cstdint>
#include <vector>

namespace airtrap {

//! Storage the sort permutes through, one array of each kind, swapped with the water's arrays
//! in turn: a fraction of a second copy of the water. A solver may lend arrays it rewrites
//! before reading them again.
struct SortSpares {
    std::vector<Vec3f>& vectors;
    std::vector<float>& scalars;
    std::vector<std::uint32_t>& ids;
};

//! Builds `grid` for the water's positions and reorders `fluid` by cell, dropping the particles
//! outside the domain (counted in report.removedParticles); `sorted` gets the positions as three
//! arrays. Reports the largest speed, found in the same sweep. The spares come back holding the
//! unsorted arrays.
void sortByCell(NeighborGrid& grid, ParticleSet& fluid, SortSpares spares, PositionArrays& sorted,
                StepReport& report);

} // namespace airtrap
