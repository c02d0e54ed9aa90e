#pragma once
// Uniform grid with cell size = kernel support radius, over the simulation domain plus one ghost
// layer on every side (so the 27-cell neighbourhood of any interior cell exists without bounds
// checks). Particles are counting-sorted by cell with x varying fastest, so each of the nine
// (y, z) rows of a neighbourhood is one contiguous range of the sorted arrays: neighbour loops
// stream memory. Rebuilt every
// step (Ihmsen et al. 2011 call this "index sort"). The sort is stable, so the result depends only
// on the input order.
#include "core/Math.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

namespace airtrap {

class NeighborGrid {
public:
    NeighborGrid(const Aabb& domain, float cellSize);

    //! Moves the grid onto `domain`, keeping the cell size and the allocations. Cheap when the
    //! domain is small, which is why a group of a few moving bodies fits its grid to them.
    void reshape(const Aabb& domain);
    //! Whether x lies in the domain (points outside it are dropped by build()). NaN is outside.
    bool contains(const Vec3f& x) const {
        return x.x() >= lower_.x() && x.x() <= upper_.x() && x.y() >= lower_.y() &&
               x.y() <= upper_.y() && x.z() >= lower_.z() && x.z() <= upper_.z();
    }

    //! Sorts the points by cell. Afterwards `order()[k]` is the input index of the k-th sorted
    //! point; points outside the domain are dropped and counted in `outsideCount()`.
    void build(const std::vector<Vec3f>& positions);

    const std::vector<std::uint32_t>& order() const { return order_; }
    std::size_t sortedCount() const { return order_.size(); }
    //! Frees what only the sort needs (order() becomes empty; the cells stay): for a grid whose
    //! points were copied in sorted order and that is not built again for a while.
    void releaseSortMemory();
    std::size_t outsideCount() const { return outside_; }

    //! Calls visit(begin, end) for the contiguous ranges of sorted indices that cover the cells
    //! within `radius` (≤ the cell size) of `x`: the nine (y, z) rows of three cells around the
    //! cell holding `x` (which must lie inside the domain), less the corner rows whose (y, z)
    //! distance from `x` is already beyond `radius` (about a fifth of them).
    template <class Visit>
    void forEachNeighborRange(const Vec3f& x, float radius, Visit&& visit) const {
        const Vec3i c = cellCoordinates(x);
        const Vec3f local = x - origin_ - c.cast<float>() * cellSize_; // position in its cell
        const float radius2 = radius * radius;
        for (int dz = -1; dz <= 1; ++dz) {
            const float gapZ = rowGap(local.z(), dz);
            for (int dy = -1; dy <= 1; ++dy) {
                const float gapY = rowGap(local.y(), dy);
                if (gapY * gapY + gapZ * gapZ >= radius2)
                    continue;
                const int rowStart = linearIndex(c.x() - 1, c.y() + dy, c.z() + dz);
                visit(cellStart_[rowStart], cellStart_[rowStart + 3]);
            }
        }
    }

    //! Calls visit(begin, end) for ranges of sorted indices that cover every point within
    //! `radius` of `centre` (any radius, unlike forEachNeighborRange): one range per (y, z) row of
    //! cells that the ball reaches, trimmed to the cells under the ball's chord along x.
    template <class Visit>
    void forEachRangeInBall(const Vec3d& centre, double radius, Visit&& visit) const {
        const double radius2 = radius * radius;
        const int lowZ = cellIndex(centre.z() - radius, 2);
        const int highZ = cellIndex(centre.z() + radius, 2);
        const int lowY = cellIndex(centre.y() - radius, 1);
        const int highY = cellIndex(centre.y() + radius, 1);
        for (int k = lowZ; k <= highZ; ++k) {
            const double gapZ = gapToCell(centre.z(), k, 2);
            for (int j = lowY; j <= highY; ++j) {
                const double gapY = gapToCell(centre.y(), j, 1);
                const double chord2 = radius2 - gapY * gapY - gapZ * gapZ;
                if (chord2 < 0.0)
                    continue;
                const double halfChord = std::sqrt(chord2);
                visit(cellStart_[linearIndex(cellIndex(centre.x() - halfChord, 0), j, k)],
                      cellStart_[linearIndex(cellIndex(centre.x() + halfChord, 0), j, k) + 1]);
            }
        }
    }
    Vec3i cellCoordinates(const Vec3f& x) const {
        const Vec3f g = (x - origin_) * invCellSize_;
        return Vec3i(clampAxis(g.x(), 0), clampAxis(g.y(), 1), clampAxis(g.z(), 2));
    }
    int linearIndex(int i, int j, int k) const { return i + dims_.x() * (j + dims_.y() * k); }

    //! Cells per axis, ghost layers included.
    const Vec3i& dimensions() const { return dims_; }
    float cellSize() const { return cellSize_; }
    //! World position of the lower corner of cell (0, 0, 0), a ghost cell.
    const Vec3f& origin() const { return origin_; }
    //! Number of sorted points in a cell: the occupancy the air-pocket flood fill reads.
    std::uint32_t cellCount(int linear) const {
        return cellStart_[linear + 1] - cellStart_[linear];
    }
    std::size_t cellTotal() const { return cellStart_.size() - 1; }
    //! The sorted indices [first, second) of the points in a cell.
    std::pair<std::uint32_t, std::uint32_t> cellRange(int linear) const {
        return {cellStart_[linear], cellStart_[linear + 1]};
    }
    std::size_t allocatedBytes() const;

private:
    //! Distance along one axis from a point at `local` in its cell to the neighbouring slab of
    //! cells at offset `d` (−1, 0, +1).
    float rowGap(float local, int d) const {
        return d < 0 ? local : (d > 0 ? cellSize_ - local : 0.0f);
    }
    //! The inner cell holding coordinate `x` along `axis`.
    int cellIndex(double x, int axis) const {
        return clampAxis(static_cast<float>((x - origin_[axis]) * invCellSize_), axis);
    }
    //! Distance along `axis` from coordinate `x` to cell `index`'s slab (0 inside it).
    double gapToCell(double x, int index, int axis) const {
        const double low = origin_[axis] + double(index) * cellSize_;
        return x < low ? low - x : std::max(0.0, x - (low + cellSize_));
    }
    int clampAxis(float g, int axis) const {
        const int i = static_cast<int>(g);
        return i < 1 ? 1 : (i > dims_[axis] - 2 ? dims_[axis] - 2 : i);
    }

    Vec3f lower_; //!< the domain's corners, in the points' precision
    Vec3f upper_;
    float cellSize_;
    float invCellSize_;
    Vec3f origin_;
    Vec3i dims_;
    std::vector<std::uint32_t> cellStart_; //!< cellTotal() + 1 offsets into the sorted order
    std::vector<std::uint32_t> cellOfPoint_;
    std::vector<std::uint32_t> order_;
    std::size_t outside_ = 0;
};

} // namespace airtrap
