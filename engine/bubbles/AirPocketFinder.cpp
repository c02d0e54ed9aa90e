#include "bubbles/AirPocketFinder.h"

#include <algorithm>

namespace airtrap {
namespace {

Vec3i coordinatesOf(const NeighborGrid& grid, int cell) {
    const Vec3i& dims = grid.dimensions();
    return Vec3i(cell % dims.x(), (cell / dims.x()) % dims.y(), cell / (dims.x() * dims.y()));
}

Vec3d centreOf(const NeighborGrid& grid, int cell) {
    const Vec3i c = coordinatesOf(grid, cell);
    return (grid.origin() + (c.cast<float>() + Vec3f::Constant(0.5f)) * grid.cellSize())
        .cast<double>();
}

//! Ghost cells (the outermost layer) exist only so neighbourhoods need no bounds checks.
bool isGhost(const NeighborGrid& grid, const Vec3i& c) {
    const Vec3i& dims = grid.dimensions();
    for (int axis = 0; axis < 3; ++axis)
        if (c[axis] == 0 || c[axis] == dims[axis] - 1)
            return true;
    return false;
}

} // namespace

std::vector<AirPocket> AirPocketFinder::find(const NeighborGrid& grid, const SolidTest& isSolid) {
    solidScratch_.assign(grid.cellTotal(), 0);
    for (int cell = 0; cell < static_cast<int>(grid.cellTotal()); ++cell)
        if (grid.cellCount(cell) == 0 && !isGhost(grid, coordinatesOf(grid, cell)))
            solidScratch_[cell] = isSolid(centreOf(grid, cell)) ? 1 : 0;
    return find(grid, solidScratch_);
}

std::vector<AirPocket> AirPocketFinder::find(const NeighborGrid& grid,
                                             const std::vector<std::uint8_t>& solid) {
    classify(grid, solid);
    floodAtmosphere(grid);
    std::vector<AirPocket> pockets;
    // In index order, so that each pocket starts from its lowest cell, as the order of equal
    // volumes below requires.
    std::sort(airCells_.begin(), airCells_.end());
    for (int cell : airCells_)
        if (cells_[cell] == Cell::Air)
            pockets.push_back(collectPocket(grid, cell));
    // Stable: equal volumes keep the order of their first cells.
    std::stable_sort(pockets.begin(), pockets.end(),
                     [](const AirPocket& a, const AirPocket& b) { return a.volume > b.volume; });
    return pockets;
}

void AirPocketFinder::classify(const NeighborGrid& grid, const std::vector<std::uint8_t>& solid) {
    // Down each column from the open top: the air reached straight from above is atmosphere
    // already. Most of the domain is such open sky, so the flood only has to visit the air under
    // water or solids (one sequential pass here instead of a queue through every air cell).
    cells_.assign(grid.cellTotal(), Cell::Blocked);
    airCells_.clear();
    const Vec3i& dims = grid.dimensions();
    for (int k = 1; k < dims.z() - 1; ++k) {
        openToSky_.assign(static_cast<std::size_t>(dims.x()), 1);
        for (int j = dims.y() - 2; j >= 1; --j)
            for (int i = 1; i < dims.x() - 1; ++i) {
                const int cell = grid.linearIndex(i, j, k);
                if (grid.cellCount(cell) != 0 || solid[cell] != 0) {
                    openToSky_[i] = 0;
                    continue;
                }
                if (openToSky_[i]) {
                    cells_[cell] = Cell::Atmosphere;
                } else {
                    cells_[cell] = Cell::Air;
                    airCells_.push_back(cell);
                }
            }
    }
}

void AirPocketFinder::floodAtmosphere(const NeighborGrid& grid) {
    // The atmosphere spreads from the open sky sideways and upwards into the air under
    // overhangs: the flood starts at the air cells beside it. Only the air cells need a look,
    // not the whole grid.
    queue_.clear();
    for (int cell : airCells_) {
        if (cells_[cell] != Cell::Air)
            continue;
        bool besideSky = false;
        forEachFaceNeighbor(grid, cell, [&](int neighbour) {
            besideSky = besideSky || cells_[neighbour] == Cell::Atmosphere;
        });
        if (besideSky) {
            cells_[cell] = Cell::Atmosphere;
            queue_.push_back(cell);
        }
    }
    for (std::size_t next = 0; next < queue_.size(); ++next)
        forEachFaceNeighbor(grid, queue_[next], [&](int neighbour) {
            if (cells_[neighbour] == Cell::Air) {
                cells_[neighbour] = Cell::Atmosphere;
                queue_.push_back(neighbour);
            }
        });
}

AirPocket AirPocketFinder::collectPocket(const NeighborGrid& grid, int seed) {
    AirPocket pocket;
    queue_.assign(1, seed);
    cells_[seed] = Cell::Pocket;
    for (std::size_t next = 0; next < queue_.size(); ++next)
        forEachFaceNeighbor(grid, queue_[next], [&](int neighbour) {
            if (cells_[neighbour] == Cell::Air) {
                cells_[neighbour] = Cell::Pocket;
                queue_.push_back(neighbour);
            }
        });
    pocket.cells = queue_;
    std::sort(pocket.cells.begin(), pocket.cells.end());
    for (int cell : pocket.cells)
        pocket.centre += centreOf(grid, cell);
    pocket.centre /= static_cast<double>(pocket.cells.size());
    const double side = grid.cellSize();
    pocket.volume = static_cast<double>(pocket.cells.size()) * side * side * side;
    return pocket;
}

template <class Visit>
void AirPocketFinder::forEachFaceNeighbor(const NeighborGrid& grid, int cell, Visit&& visit) const {
    const Vec3i& dims = grid.dimensions();
    const int strides[3] = {1, dims.x(), dims.x() * dims.y()};
    for (int stride : strides) {
        // Ghost cells are Blocked, so stepping onto one is harmless and stepping past one
        // cannot happen from an inner cell.
        visit(cell - stride);
        visit(cell + stride);
    }
}

} // namespace airtrap
