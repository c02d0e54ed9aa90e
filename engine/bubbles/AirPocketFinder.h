#pragma once
// Finds trapped air pockets on the water's neighbour grid (paper §3.4, docs/METHOD.md "Creation"):
// a cell is air when it holds no water particle and is not inside a solid (a rigid body or an
// existing bubble). A 6-connected flood fill from the air cells of the grid's top layer — the
// open top of the domain — marks the atmosphere; the air cells it does not reach form connected
// components, the pockets. Reuses the grid the step already built; a sweep down the columns
// settles the open sky and lists the air under water or solids, so finding pockets costs one
// pass over the cells and a flood through that air.
#include "bubbles/AirPocket.h"
#include "sph/NeighborGrid.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace airtrap {

class AirPocketFinder {
public:
    //! Whether the cell centred at a world point lies inside a solid.
    using SolidTest = std::function<bool(const Vec3d& cellCentre)>;

    //! The pockets of `grid` (built on the water's positions), largest first, ties broken by
    //! the lowest cell index so the order is deterministic.
    std::vector<AirPocket> find(const NeighborGrid& grid, const SolidTest& isSolid);
    //! The same with the solid cells given as a mask, one byte per grid cell (non-zero: solid):
    //! what the simulation uses, one pass over the cells without a query per cell.
    std::vector<AirPocket> find(const NeighborGrid& grid, const std::vector<std::uint8_t>& solid);

private:
    enum class Cell : std::uint8_t { Blocked, Air, Atmosphere, Pocket };

    void classify(const NeighborGrid& grid, const std::vector<std::uint8_t>& solid);
    void floodAtmosphere(const NeighborGrid& grid);
    //! Marks the pocket holding `seed` and returns it.
    AirPocket collectPocket(const NeighborGrid& grid, int seed);
    //! Calls visit(neighbour) for the 6 face neighbours of `cell` that are not ghost cells.
    template <class Visit>
    void forEachFaceNeighbor(const NeighborGrid& grid, int cell, Visit&& visit) const;

    std::vector<Cell> cells_;
    std::vector<int> airCells_; //!< the cells classify() found Air: under water or a solid
    std::vector<int> queue_;
    std::vector<std::uint8_t> solidScratch_;
    std::vector<std::uint8_t> openToSky_; //!< per x in the current column sweep
};

} // namespace airtrap
