#pragma once
// The boundary particles of a group of rigid bodies in world space, sorted on their own
// neighbour grid: the water's cell lattice, cut down to the cells around the particles. A few
// bubbles or a body then cost a grid of their own size, not the domain's, when the moving layer is
// re-sorted every step. Each carries Ψ_b = ρ₀ V_b, the mass it stands
// in for in the water's density rate and pressure force (Akinci et al. 2012), its normal for the
// contact impulse (paper eq. 4), its velocity and the index of its body.
#include "rigid/RigidBody.h"
#include "sph/NeighborGrid.h"

#include <cstdint>
#include <vector>

namespace airtrap {

class BoundaryLayer {
public:
    BoundaryLayer(const Aabb& gridDomain, float cellSize, float restDensity);

    //! Gathers the boundary particles of bodies[members[…]] at their current poses and sorts
    //! them.
    void rebuild(const std::vector<RigidBody>& bodies, const std::vector<std::uint32_t>& members);

    std::size_t size() const { return positions_.size(); }
    const NeighborGrid& grid() const { return grid_; }
    const std::vector<Vec3f>& positions() const { return positions_; }
    const std::vector<Vec3f>& normals() const { return normals_; }
    const std::vector<Vec3f>& velocities() const { return velocities_; }
    const std::vector<float>& psi() const { return psi_; }
    //! Index into the bodies of rebuild() of each sorted particle's body.
    const std::vector<std::uint32_t>& bodyOf() const { return bodyOf_; }
    //! Whether any particle of the layer lies in the 27 cells around x's cell: when not, a water
    //! particle at x skips the layer's neighbour sweep (most of the water is far from the walls
    //! and from any moving body).
    bool reaches(const Vec3f& x) const {
        if (!grid_.contains(x))
            return false;
        const Vec3i c = grid_.cellCoordinates(x);
        return nearCells_[grid_.linearIndex(c.x(), c.y(), c.z())] != 0;
    }
    std::size_t allocatedBytes() const;

private:
    //! The layer's particles in the bodies' order, before sorting: held only while rebuilding
    //! (the tank's walls alone are about as many particles as the water, 44 bytes each).
    struct Unsorted {
        std::vector<Vec3f> positions;
        std::vector<Vec3f> normals;
        std::vector<Vec3f> velocities;
        std::vector<float> psi;
        std::vector<std::uint32_t> bodyOf;
    };

    //! Writes the world-space data of `body`'s particles into `unsorted` from `first`.
    void placeBody(const RigidBody& body, std::uint32_t index, std::size_t first,
                   Unsorted& unsorted) const;
    //! The cells of the water's lattice from one cell below the particles to one above, within
    //! the lattice's domain: every point within a cell of a particle lies inside.
    Aabb window(const std::vector<Vec3f>& positions) const;
    //! Marks the cells whose 27-cell neighbourhood holds a particle.
    void markReach();

    float restDensity_;
    Aabb latticeDomain_; //!< the water grid's domain, whose cells the layer's grid reuses
    float cellSize_;
    NeighborGrid grid_;
    std::vector<Vec3f> positions_;
    std::vector<Vec3f> normals_;
    std::vector<Vec3f> velocities_;
    std::vector<float> psi_;
    std::vector<std::uint32_t> bodyOf_;
    std::vector<std::uint8_t> nearCells_; //!< per cell: a particle within one cell
};

} // namespace airtrap
