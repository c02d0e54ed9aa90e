#include "sph/BoundaryLayer.h"

#include <limits>

namespace airtrap {

BoundaryLayer::BoundaryLayer(const Aabb& gridDomain, float cellSize, float restDensity)
    : restDensity_(restDensity), latticeDomain_(gridDomain), cellSize_(cellSize),
      grid_(gridDomain, cellSize) {}

void BoundaryLayer::rebuild(const std::vector<RigidBody>& bodies,
                            const std::vector<std::uint32_t>& members) {
    std::size_t total = 0;
    for (std::uint32_t index : members)
        total += bodies[index].boundary().size();
    Unsorted unsorted;
    unsorted.positions.resize(total);
    unsorted.normals.resize(total);
    unsorted.velocities.resize(total);
    unsorted.psi.resize(total);
    unsorted.bodyOf.resize(total);
    std::size_t first = 0;
    for (std::uint32_t index : members) {
        placeBody(bodies[index], index, first, unsorted);
        first += bodies[index].boundary().size();
    }
    grid_.reshape(window(unsorted.positions));
    grid_.build(unsorted.positions);
    const auto& order = grid_.order();
    const std::size_t n = order.size();
    positions_.resize(n);
    normals_.resize(n);
    velocities_.resize(n);
    psi_.resize(n);
    bodyOf_.resize(n);
    for (std::size_t s = 0; s < n; ++s) {
        const std::uint32_t from = order[s];
        positions_[s] = unsorted.positions[from];
        normals_[s] = unsorted.normals[from];
        velocities_[s] = unsorted.velocities[from];
        psi_[s] = unsorted.psi[from];
        bodyOf_[s] = unsorted.bodyOf[from];
    }
    grid_.releaseSortMemory();
    markReach();
}

Aabb BoundaryLayer::window(const std::vector<Vec3f>& positions) const {
    Aabb bounds{Vec3d::Constant(std::numeric_limits<double>::max()),
                Vec3d::Constant(std::numeric_limits<double>::lowest())};
    for (const Vec3f& x : positions) {
        if (!x.allFinite()) // a blown-up body: build() drops the point, the guard reports it
            continue;
        bounds.min = bounds.min.cwiseMin(x.cast<double>());
        bounds.max = bounds.max.cwiseMax(x.cast<double>());
    }
    const Vec3d latticeMin = latticeDomain_.min; // a cell corner of the water's grid
    if (!(bounds.min.array() <= bounds.max.array()).all())
        return {latticeMin, latticeMin + Vec3d::Constant(cellSize_)};
    // Snapped outwards to whole cells, so the layer's cells are the water grid's cells and its
    // particles sort in the same order as on a grid over the whole domain.
    const auto snap = [&](const Vec3d& x, double cells) {
        const Vec3d index = ((x - latticeMin) / cellSize_).array().floor() + cells;
        return Vec3d(latticeMin + index * cellSize_);
    };
    return {snap(bounds.min, -1.0).cwiseMax(latticeDomain_.min).cwiseMin(latticeDomain_.max),
            snap(bounds.max, 2.0).cwiseMin(latticeDomain_.max).cwiseMax(latticeDomain_.min)};
}

void BoundaryLayer::markReach() {
    nearCells_.assign(grid_.cellTotal(), 0);
    // Particles are never in ghost cells (the grid puts them in the inner cells), so their
    // neighbours are inside the grid. Sorted by cell, each cell is marked around once.
    int previous = -1;
    for (const Vec3f& x : positions_) {
        const Vec3i c = grid_.cellCoordinates(x);
        const int cell = grid_.linearIndex(c.x(), c.y(), c.z());
        if (cell == previous)
            continue;
        previous = cell;
        for (int dz = -1; dz <= 1; ++dz)
            for (int dy = -1; dy <= 1; ++dy) {
                const int row = grid_.linearIndex(c.x() - 1, c.y() + dy, c.z() + dz);
                nearCells_[row] = nearCells_[row + 1] = nearCells_[row + 2] = 1;
            }
    }
}

void BoundaryLayer::placeBody(const RigidBody& body, std::uint32_t index, std::size_t first,
                              Unsorted& unsorted) const {
    const BoundaryParticles& local = body.boundary();
    for (std::size_t b = 0; b < local.size(); ++b) {
        const Vec3f x = body.toWorld(local.positions[b]);
        unsorted.positions[first + b] = x;
        unsorted.normals[first + b] = body.directionToWorld(local.normals[b]);
        unsorted.velocities[first + b] = body.velocityAt(x);
        unsorted.psi[first + b] = restDensity_ * local.volumes[b];
        unsorted.bodyOf[first + b] = index;
    }
}

std::size_t BoundaryLayer::allocatedBytes() const {
    return grid_.allocatedBytes() +
           (positions_.capacity() + normals_.capacity() + velocities_.capacity()) * sizeof(Vec3f) +
           psi_.capacity() * sizeof(float) + bodyOf_.capacity() * sizeof(std::uint32_t) +
           nearCells_.capacity();
}

} // namespace airtrap
