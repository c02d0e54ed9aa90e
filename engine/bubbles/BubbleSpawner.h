#pragma once
// Creates bubbles in the air pockets the water encloses (paper §3.4, docs/METHOD.md "Creation"):
// finds the pockets on the step's neighbour grid (cells inside a rigid body or an existing bubble
// are not air), fits a bubble to each, keeps those under water, and turns up to a given number of
// them, chosen at random with the scene's seed and the step count, into bubbles moving with the
// water around them. Under water means that water wets at least `bubbles.min_water_share` of
// BubbleImmersion's 26 probes around the bubble and kLidProbes of the 9 above its equator: the
// grid's cells are two spacings wide, so the sparse spray of a splash's crown encloses "pockets"
// that are open air between droplets; a bubble made there would be out of the water at once.
#include "bubbles/AirPocketFinder.h"
#include "bubbles/BubbleFitter.h"
#include "bubbles/BubbleImmersion.h"
#include "bubbles/BubbleState.h"
#include "rigid/RigidBody.h"
#include "scene/Scene.h"
#include "sph/NeighborSweep.h"
#include "sph/ParticleSet.h"

#include <vector>

namespace airtrap {

class BubbleSpawner {
public:
    BubbleSpawner(const BubbleSettings& settings, double spacing, std::uint64_t seed);

    //! The water as the spawner reads it: the grid of the last step, its sorted positions, and
    //! the state's particles in that order (their velocities).
    struct Water {
        const NeighborGrid& grid;
        const PositionArrays& positions;
        const ParticleSet& particles;
    };

    //! The living bubbles, oldest first, and the id the next new one takes.
    struct Bubbles {
        std::vector<BubbleState>& alive;
        std::uint32_t& nextId;
    };

    //! Adds at most `limit` new bubbles to `bubbles`, born in `frame` at the step numbered
    //! `step` (since t = 0); `solids` are the rigid bodies bubbles may not start in (not the
    //! bubbles' own bodies). Returns how many were made.
    std::size_t spawn(const Bubbles& bubbles, std::uint64_t step, const Water& water,
                      const std::vector<const RigidBody*>& solids, int frame, std::size_t limit);

private:
    //! Marks in solid_ the cells of `grid` that reach into a body or a bubble. The static bodies'
    //! cells are found once (the grid's layout never changes); moving bodies and bubbles mark
    //! only the cells around them, so a search costs a pass over the cells, not one distance
    //! query per cell and body.
    void markSolidCells(const NeighborGrid& grid, const std::vector<BubbleState>& bubbles,
                        const std::vector<const RigidBody*>& solids);
    //! Marks the cells within `reach` of `centre` for which `inside(cellCentre)` holds.
    template <class Inside>
    void markAround(const NeighborGrid& grid, const Vec3d& centre, double reach,
                    std::vector<std::uint8_t>& mask, Inside&& inside) const;
    //! The fitted bubbles that keep half a spacing from every body, as candidates.
    std::vector<FittedBubble> candidates(const std::vector<AirPocket>& pockets, const Water& water,
                                         const std::vector<const RigidBody*>& solids) const;
    //! Whether the fitted bubble is under water (see the top of this file).
    bool underWater(const FittedBubble& bubble, const Water& water) const;
    //! Wet probes above the equator that make a lid of water over a new bubble. Not all 9, nor
    //! the one straight up: the cavity a plunging jet drives into deep water is a tall pocket,
    //! and a bubble fitted in its lower part looks up into air that is still enclosed.
    static constexpr int kLidProbes = 3;
    //! Whether the water closes over the bubble: kLidProbes of its upper probes are wet.
    bool coveredFromAbove(const BubbleImmersion::WetProbes& wet) const;
    //! The mean velocity of the water within one support radius of the bubble's surface.
    Vec3d surroundingVelocity(const FittedBubble& bubble, const Water& water) const;

    BubbleSettings settings_;
    double spacing_;
    std::uint64_t seed_;
    AirPocketFinder finder_;
    BubbleFitter fitter_;
    BubbleImmersion immersion_;
    BubbleImmersion::WetProbes upperProbes_; //!< the probes above a bubble's equator
    int minWetProbes_;                       //!< wet probes a new bubble needs
    std::vector<std::uint8_t> staticSolid_;  //!< per grid cell: reaches into a static body
    std::vector<std::uint8_t> solid_;        //!< the same with moving bodies and bubbles
};

} // namespace airtrap
