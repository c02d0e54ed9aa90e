#pragma once
// The deletion rules of paper §3.4, checked after every step: a bubble is deleted when (1) it is
// older than the maximum age, (2) it has floated at the free surface longer than the maximum
// floating time, (3) it overlaps another bubble by more than the maximum share of the smaller
// one's diameter (the smaller one goes), or (4) it floats and water hits it faster than the
// impact speed; and (5, `surfaced`) at once when it has left the water. Floating and out of the
// water are judged by BubbleImmersion's probes: floating with 7–12 of the 26 wet, out of the
// water with fewer. Each deletion is counted under its rule.
#include "bubbles/BubbleState.h"
#include "bubbles/BubbleSurroundings.h"
#include "bubbles/BubbleTally.h"
#include "scene/Scene.h"

#include <vector>

namespace airtrap {

class BubbleDeletion {
public:
    explicit BubbleDeletion(const BubbleSettings& settings) : settings_(settings) {}

    //! Ages the bubbles by `dt` s, updates their floating time from their surroundings as last
    //! measured and deletes those a rule condemns.
    void afterStep(std::vector<BubbleState>& bubbles, double dt, BubbleTally& tally) const;

private:
    //! The rule that deletes `bubble`, or RuleCount when none does (overlap aside).
    BubbleTally::Rule ownRule(const BubbleState& bubble, const BubbleSurroundings* around,
                              bool wasFloating) const;
    //! Marks the smaller of every pair overlapping beyond the limit.
    void markOverlaps(const std::vector<BubbleState>& bubbles,
                      std::vector<BubbleTally::Rule>& verdicts) const;

    BubbleSettings settings_;
};

} // namespace airtrap
