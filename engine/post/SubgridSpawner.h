#pragma once
// Sheds the sub-grid bubbles of a newly trapped bubble (paper §4.2). A trapped bubble is smaller
// than its pocket of grid cells; the gap is air too fine for the grid. The less of the bubble's
// surface lies in water (its area fraction in water, recorded at its creation), the wider that
// gap, and the more small bubbles it sheds. Their sites are vertices of three concentric spheres
// around it, outside it, chosen at random; their radii are random within the size bounds. Each
// sub-grid bubble of a generation before the last sheds smaller ones around itself the same way.
// The random sequence depends only on the seed and the parent's id, so a post run gives the same
// bubbles whatever the order of frames or threads.
#include "bubbles/BubbleState.h"
#include "post/SubgridBubble.h"
#include "scene/Scene.h"

#include <cstdint>
#include <random>
#include <vector>

namespace airtrap {

class SubgridSpawner {
public:
    //! Sites on each of the three spheres (the vertices of a once-subdivided icosahedron).
    static constexpr int kSitesPerShell = 42;
    //! Radii of the three spheres, as multiples of the parent's radius.
    static constexpr double kShellRadii[3] = {1.25, 1.5, 1.75};

    //! Throws Error(InvalidInput) for settings out of range.
    SubgridSpawner(const SubgridBubbleSettings& settings, std::uint64_t seed);

    //! How many a new bubble with this area fraction in water sheds itself (generation 1).
    int countFor(double areaFractionInWater) const;
    //! Every generation shed by `parent` at its birth. Ids run on from `nextId`, which is
    //! advanced past them.
    std::vector<SubgridBubble> shed(const BubbleState& parent, std::uint32_t& nextId) const;

private:
    void shedAround(const SubgridBubble& parent, int count, std::mt19937_64& random,
                    std::uint32_t& nextId, std::vector<SubgridBubble>& out) const;

    SubgridBubbleSettings settings_;
    std::uint64_t seed_;
    std::vector<Vec3d> directions_;
};

} // namespace airtrap
