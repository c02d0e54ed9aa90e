#pragma once
// The boundary particles of every rigid body, in two layers: the static bodies' (the container,
// obstacles, static scene bodies), placed and sorted once, and the moving bodies' (dynamic,
// kinematic, bubbles), placed and sorted every step. Apart, a bubble or a dropped ball costs a
// sort of its own few particles per step, not of the whole tank's. Also the contact terms of
// every body (paper eq. 4).
#include "sph/BodyContactTerms.h"
#include "sph/BoundaryLayer.h"
#include "sph/NeighborSweep.h"

#include <array>
#include <cstdint>
#include <vector>

namespace airtrap {

class BoundaryModel {
public:
    BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity);

    //! Places the bodies at their current poses: the static ones only the first time (or when
    //! the set of static bodies changed), the moving ones every time.
    void rebuild(const std::vector<RigidBody>& bodies);

    const BoundaryLayer& staticLayer() const { return static_; }
    //! Holds every dynamic body's particles: the water's reaction is gathered here.
    const BoundaryLayer& movingLayer() const { return moving_; }
    std::array<const BoundaryLayer*, 2> layers() const { return {&static_, &moving_}; }

    //! Notes which water particles (sorted, on `waterGrid`) lie within `supportRadius` of a
    //! moving layer's particle, by sweeping the water around each of those particles. The
    //! layer's cell mask (BoundaryLayer::reaches) would send every water particle within a cell
    //! of a bubble through the layer's sweep in both passes, about twice as many as touch it;
    //! for the few hundred particles of bubbles and bodies this sweep is the cheaper test.
    //! Call after rebuild() and after the water's sort, every step the moving layer is used.
    void markWaterNearMovingLayer(const NeighborGrid& waterGrid, const PositionArrays& water,
                                  float supportRadius);
    //! Whether layer `layer` (one of layers()) may have particles within the support radius of
    //! sorted water particle `i` at `x`: the water mark for the moving layer, the cell mask for
    //! the static one.
    bool mayReach(const BoundaryLayer* layer, std::size_t i, const Vec3f& x) const {
        if (layer == &moving_)
            return nearMoving_[i] != 0;
        return layer->reaches(x);
    }
    std::size_t size() const { return static_.size() + moving_.size(); }
    const BodyContactTerms& contactTerms(std::uint32_t body) const { return terms_[body]; }
    //! Whether any body is dynamic, so that the water's reaction must be gathered.
    bool hasDynamicBodies() const { return hasDynamicBodies_; }
    std::size_t allocatedBytes() const;

private:
    void gatherTerms(const std::vector<RigidBody>& bodies);

    BoundaryLayer static_;
    BoundaryLayer moving_;
    std::vector<std::uint32_t> staticMembers_;
    std::vector<std::uint32_t> movingMembers_;
    bool staticPlaced_ = false;
    std::vector<BodyContactTerms> terms_;
    bool hasDynamicBodies_ = false;
    std::vector<std::uint8_t> nearMoving_; //!< per sorted water particle: 1 near the moving layer
};

} // namespace airtrap
