#include "sph/NeighborGrid.h"

#include "core/Parallel.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace airtrap {

namespace {
constexpr std::uint32_t kOutside = std::numeric_limits<std::uint32_t>::max();
}

NeighborGrid::NeighborGrid(const Aabb& domain, float cellSize)
    : cellSize_(cellSize), invCellSize_(1.0f / cellSize) {
    reshape(domain);
}

void NeighborGrid::reshape(const Aabb& domain) {
    // Rounded outwards, so a point inside the double-precision domain is inside these bounds.
    lower_ = domain.min.cast<float>();
    upper_ = domain.max.cast<float>();
    for (int axis = 0; axis < 3; ++axis) {
        if (double(lower_[axis]) > domain.min[axis])
            lower_[axis] = std::nextafter(lower_[axis], -std::numeric_limits<float>::infinity());
        if (double(upper_[axis]) < domain.max[axis])
            upper_[axis] = std::nextafter(upper_[axis], std::numeric_limits<float>::infinity());
    }
    origin_ = domain.min.cast<float>() - Vec3f::Constant(cellSize_);
    for (int axis = 0; axis < 3; ++axis) {
        const double cells = std::ceil(domain.size()[axis] / cellSize_);
        dims_[axis] = static_cast<int>(std::max(cells, 1.0)) + 2;
    }
    cellStart_.assign(static_cast<std::size_t>(dims_.prod()) + 1, 0);
}

void NeighborGrid::build(const std::vector<Vec3f>& positions) {
    const std::size_t n = positions.size();
    cellOfPoint_.resize(n);
    parallelFor(tbb::blocked_range<std::size_t>(0, n, 4096), [&](const auto& range) {
        for (std::size_t p = range.begin(); p != range.end(); ++p) {
            const Vec3f& x = positions[p];
            if (!contains(x)) {
                cellOfPoint_[p] = kOutside;
                continue;
            }
            const Vec3i c = cellCoordinates(x);
            cellOfPoint_[p] = static_cast<std::uint32_t>(linearIndex(c.x(), c.y(), c.z()));
        }
    });

    // Stable counting sort. Serial: at ~1 ns per point it costs less than the imbalance a
    // parallel histogram would add at these sizes, and it keeps the order trivially deterministic.
    std::fill(cellStart_.begin(), cellStart_.end(), 0u);
    outside_ = 0;
    for (std::size_t p = 0; p < n; ++p) {
        if (cellOfPoint_[p] == kOutside)
            ++outside_;
        else
            ++cellStart_[cellOfPoint_[p] + 1];
    }
    for (std::size_t c = 1; c < cellStart_.size(); ++c)
        cellStart_[c] += cellStart_[c - 1];
    order_.resize(n - outside_);
    std::vector<std::uint32_t>& cursor = cellOfPoint_; // reused: each point's slot after the sort
    for (std::size_t p = 0; p < n; ++p) {
        const std::uint32_t cell = cursor[p];
        if (cell != kOutside)
            order_[cellStart_[cell]++] = static_cast<std::uint32_t>(p);
    }
    // The scatter advanced every start to the next cell's start: shift back by one cell.
    for (std::size_t c = cellStart_.size() - 1; c > 0; --c)
        cellStart_[c] = cellStart_[c - 1];
    cellStart_[0] = 0;
}

void NeighborGrid::releaseSortMemory() {
    std::vector<std::uint32_t>().swap(cellOfPoint_);
    std::vector<std::uint32_t>().swap(order_);
}

std::size_t NeighborGrid::allocatedBytes() const {
    return (cellStart_.capacity() + cellOfPoint_.capacity() + order_.capacity()) *
           sizeof(std::uint32_t);
}

} // namespace airtrap
