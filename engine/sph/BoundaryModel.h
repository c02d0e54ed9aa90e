#pragma once
// The boundary particles of every rigid body in world space, sorted on their own neighbour grid
// (same cell layout as the water's). Each carries Ψ_b = ρ₀ V_b, the mass it stands in for in the
// water's density rate and pressure force (Akinci et al. 2012), its normal for the contact
// impulse (paper eq. 4), its velocity and the index of its body.
#include "rigid/RigidBody.h"
#include "sph/BodyContactTerms.h"
#include "sph/NeighborGrid.h"

#include <cstdint>
#include <vector>

namespace airtrap {

class BoundaryModel {
public:
    BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity);

    //! Gathers the bodies' boundary particles in world space at their current poses and sorts
    //! them.
    void rebuild(const std::vector<RigidBody>& bodies);

    std::size_t size() const { return positions_.size(); }
    const NeighborGrid& grid() const { return grid_; }
    const std::vector<Vec3f>& positions() const { return positions_; }
    const std::vector<Vec3f>& normals() const { return normals_; }
    const std::vector<Vec3f>& velocities() const { return velocities_; }
    const std::vector<float>& psi() const { return psi_; }
    //! Index into the bodies of rebuild() of each sorted particle's body.
    const std::vector<std::uint32_t>& bodyOf() const { return bodyOf_; }
    const BodyContactTerms& contactTerms(std::uint32_t body) const { return terms_[body]; }
    //! Whether any body is dynamic, so that the water's reaction must be gathered.
    bool hasDynamicBodies() const { return hasDynamicBodies_; }
    std::size_t allocatedBytes() const;

private:
    //! Writes the world-space data of `bodies[index]`'s particles into the unsorted arrays from
    //! `first` on.
    void placeBody(const std::vector<RigidBody>& bodies, std::size_t index, std::size_t first);
    void gatherTerms(const std::vector<RigidBody>& bodies);

    float restDensity_;
    NeighborGrid grid_;
    std::vector<Vec3f> positions_;
    std::vector<Vec3f> normals_;
    std::vector<Vec3f> velocities_;
    std::vector<float> psi_;
    std::vector<std::uint32_t> bodyOf_;
    std::vector<BodyContactTerms> terms_;
    // The same in the bodies' order, before sorting; kept between rebuilds so that static
    // bodies, whose particles never move, are placed once.
    std::vector<Vec3f> unsortedPositions_;
    std::vector<Vec3f> unsortedNormals_;
    std::vector<Vec3f> unsortedVelocities_;
    std::vector<float> unsortedPsi_;
    std::vector<std::uint32_t> unsortedBodyOf_;
    std::size_t placedBodies_ = 0; //!< how many bodies the unsorted arrays were built for
    bool hasDynamicBodies_ = false;
};

} // namespace airtrap
