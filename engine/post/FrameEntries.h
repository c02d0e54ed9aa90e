#pragma once
// The post stores' lists of per-frame entries, kept sorted by frame so lookups are binary
// searches. `Entry` has an `int frame` member.
#include <algorithm>
#include <type_traits>
#include <vector>

namespace airtrap {

template <class Entry>
void sortByFrame(std::vector<Entry>& entries) {
    std::sort(entries.begin(), entries.end(),
              [](const Entry& a, const Entry& b) { return a.frame < b.frame; });
}

//! The first entry at or after `frame`; `Entries` is a vector of entries, const or not.
template <class Entries>
auto lowerBoundFrame(Entries& entries, int frame) {
    using Entry = typename std::remove_const_t<Entries>::value_type;
    return std::lower_bound(entries.begin(), entries.end(), frame,
                            [](const Entry& entry, int wanted) { return entry.frame < wanted; });
}

//! The entry of `frame`, or null.
template <class Entry>
const Entry* findFrame(const std::vector<Entry>& entries, int frame) {
    const auto at = lowerBoundFrame(entries, frame);
    return at != entries.end() && at->frame == frame ? &*at : nullptr;
}

//! Replaces the entry of `entry.frame`, or inserts it in order.
template <class Entry>
void putFrame(std::vector<Entry>& entries, const Entry& entry) {
    const auto at = lowerBoundFrame(entries, entry.frame);
    if (at != entries.end() && at->frame == entry.frame)
        *at = entry;
    else
        entries.insert(at, entry);
}

} // namespace airtrap
