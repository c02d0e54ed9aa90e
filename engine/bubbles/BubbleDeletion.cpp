#include "bubbles/BubbleDeletion.h"

#include <algorithm>

namespace airtrap {

void BubbleDeletion::afterStep(std::vector<BubbleState>& bubbles, double dt,
                               BubbleTally& tally) const {
    std::vector<BubbleTally::Rule> verdicts(bubbles.size(), BubbleTally::RuleCount);
    for (std::size_t k = 0; k < bubbles.size(); ++k) {
        BubbleState& bubble = bubbles[k];
        const BubbleSurroundings* around =
            bubble.surroundings.measured ? &bubble.surroundings : nullptr;
        // Water landing on a floating bubble covers it in the step it hits: the bubble was
        // floating if it floated up to this step.
        const bool floating = around && around->placement() == BubbleImmersion::Placement::Floating;
        const bool wasFloating = bubble.floatingTime > 0.0 || floating;
        bubble.age += dt;
        bubble.floatingTime = floating ? bubble.floatingTime + dt : 0.0;
        verdicts[k] = ownRule(bubble, around, wasFloating);
    }
    markOverlaps(bubbles, verdicts);
    std::size_t kept = 0;
    for (std::size_t k = 0; k < bubbles.size(); ++k) {
        if (verdicts[k] != BubbleTally::RuleCount) {
            ++tally.deleted[verdicts[k]];
            if (verdicts[k] == BubbleTally::Surfaced && bubbles[k].age < BubbleTally::kYoungAge)
                ++tally.surfacedYoung;
            continue;
        }
        bubbles[kept++] = bubbles[k];
    }
    bubbles.resize(kept);
}

BubbleTally::Rule BubbleDeletion::ownRule(const BubbleState& bubble,
                                          const BubbleSurroundings* around,
                                          bool wasFloating) const {
    if (bubble.age > settings_.maxAge)
        return BubbleTally::Age;
    // Out of the water a bubble is air among air: it has popped (paper §3.4 deletes a bubble at
    // the surface; one the water no longer holds is past it).
    if (around && around->placement() == BubbleImmersion::Placement::Airborne)
        return BubbleTally::Surfaced;
    if (bubble.floatingTime > settings_.maxFloatingTime)
        return BubbleTally::Floating;
    if (around && wasFloating && around->impactSpeed > settings_.impactSpeed)
        return BubbleTally::Impact;
    return BubbleTally::RuleCount;
}

void BubbleDeletion::markOverlaps(const std::vector<BubbleState>& bubbles,
                                  std::vector<BubbleTally::Rule>& verdicts) const {
    for (std::size_t a = 0; a < bubbles.size(); ++a)
        for (std::size_t b = a + 1; b < bubbles.size(); ++b) {
            if (verdicts[a] != BubbleTally::RuleCount || verdicts[b] != BubbleTally::RuleCount)
                continue;
            const double ra = bubbles[a].radius;
            const double rb = bubbles[b].radius;
            const double distance = (bubbles[a].body.position - bubbles[b].body.position).norm();
            const double depth = ra + rb - distance;
            if (depth <= settings_.maxOverlap * 2.0 * std::min(ra, rb))
                continue;
            // The smaller goes; of two equal ones the younger (b: bubbles are oldest first).
            verdicts[rb <= ra ? b : a] = BubbleTally::Overlap;
        }
}

} // namespace airtrap
