#pragma once
// The boundary particles of every rigid body, in two layers: the static bodies' (the container,
// obstacles, static scene bodies), placed and sorted once, and the moving bodies' (dynamic,
// kinematic, bubbles), placed and sorted every step. Apart, a bubble or a dropped ball costs a
// sort of its own few particles per step, not of the whole tank's. Also the contact terms of
// every body (paper eq. 4).
#include "sph/BodyContactTerms.h"
#include "sph/BoundaryLayer.h"
#include "sph/MovingLayerPairs.h"
#include "sph/NeighborSweep.h"

#include <cstdint>
#include <limits>
#include <vector>

namespace airtrap {

class BoundaryModel {
public:
    BoundaryModel(const Aabb& gridDomain, float cellSize, float restDensity);

    //! Places the bodies at their current poses: the static ones only the first time (or when
    //! the set of static bodies changed), the moving ones every time. The bodies from index
    //! `firstBubble` on are bubbles'.
    void rebuild(const std::vector<RigidBody>& bodies, std::size_t firstBubble = kNoBubbles);
    static constexpr std::size_t kNoBubbles = std::numeric_limits<std::size_t>::max();

    const BoundaryLayer& staticLayer() const { return static_; }
    //! Holds every dynamic body's particles: the water's reaction is gathered here.
    const BoundaryLayer& movingLayer() const { return moving_; }

    //! Finds the pairs of sorted water particles (on `waterGrid`) and moving-layer particles
    //! within `supportRadius` (MovingLayerPairs). Call after rebuild() and after the water's
    //! sort, every step the moving layer is used.
    void findMovingLayerPairs(const NeighborGrid& waterGrid, const PositionArrays& water,
                              float supportRadius) {
        movingPairs_.find(moving_, waterGrid, water, supportRadius);
    }
    const MovingLayerPairs& movingPairs() const { return movingPairs_; }
    std::size_t size() const { return static_.size() + moving_.size(); }
    const BodyContactTerms& contactTerms(std::uint32_t body) const { return terms_[body]; }
    //! Whether any body is dynamic, so that the water's reaction must be gathered.
    bool hasDynamicBodies() const { return hasDynamicBodies_; }
    std::size_t allocatedBytes() const;

private:
    void gatherTerms(const std::vector<RigidBody>& bodies, std::size_t firstBubble);

    BoundaryLayer static_;
    BoundaryLayer moving_;
    std::vector<std::uint32_t> staticMembers_;
    std::vector<std::uint32_t> movingMembers_;
    bool staticPlaced_ = false;
    std::vector<BodyContactTerms> terms_;
    bool hasDynamicBodies_ = false;
    MovingLayerPairs movingPairs_;
};

} // namespace airtrap
