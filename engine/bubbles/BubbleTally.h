#pragma once
// How many bubbles were created and deleted, per deletion rule of paper §3.4. Kept per frame in
// the frame statistics and as running totals in the state (so a resumed bake keeps counting).
#include <array>
#include <cstdint>
#include <numeric>
#include <string_view>

namespace airtrap {

struct BubbleTally {
    enum Rule { Age, Floating, Overlap, Impact, RuleCount };
    //! The rules' names in `info --json` and the editor.
    static constexpr std::array<std::string_view, RuleCount> kRuleNames = {"age", "floating",
                                                                           "overlap", "impact"};

    std::uint64_t created = 0;
    std::array<std::uint64_t, RuleCount> deleted{};

    std::uint64_t deletedTotal() const {
        return std::accumulate(deleted.begin(), deleted.end(), std::uint64_t{0});
    }
    BubbleTally& operator+=(const BubbleTally& other) {
        created += other.created;
        for (int rule = 0; rule < RuleCount; ++rule)
            deleted[rule] += other.deleted[rule];
        return *this;
    }
    bool operator==(const BubbleTally& other) const = default;
};

} // namespace airtrap
