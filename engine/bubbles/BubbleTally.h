#pragma once
// How many bubbles were created and deleted, per deletion rule: the four of paper §3.4 and
// `surfaced`, a bubble out of the water (docs/METHOD.md, "Deletion"). Kept per frame in the frame
// statistics and as running totals in the state (so a resumed bake keeps counting).
#include <array>
#include <cstdint>
#include <numeric>
#include <string_view>

namespace airtrap {

struct BubbleTally {
    enum Rule { Age, Floating, Overlap, Impact, Surfaced, RuleCount };
    //! The rules' names in `info --json` and the editor.
    static constexpr std::array<std::string_view, RuleCount> kRuleNames = {
        "age", "floating", "overlap", "impact", "surfaced"};
    //! s: a bubble that surfaces younger than this was made at the surface, not risen to it.
    static constexpr double kYoungAge = 0.1;

    std::uint64_t created = 0;
    std::array<std::uint64_t, RuleCount> deleted{};
    //! Of the `surfaced` deletions, those of bubbles younger than kYoungAge.
    std::uint64_t surfacedYoung = 0;

    std::uint64_t deletedTotal() const {
        return std::accumulate(deleted.begin(), deleted.end(), std::uint64_t{0});
    }
    BubbleTally& operator+=(const BubbleTally& other) {
        created += other.created;
        for (int rule = 0; rule < RuleCount; ++rule)
            deleted[rule] += other.deleted[rule];
        surfacedYoung += other.surfacedYoung;
        return *this;
    }
    bool operator==(const BubbleTally& other) const = default;
};

} // namespace airtrap
