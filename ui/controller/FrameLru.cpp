#include "controller/FrameLru.h"

#include <algorithm>

namespace airtrap {

FrameLru::FrameLru() : FrameLru(Limits{}) {}

FrameLru::FrameLru(Limits limits) : limits_(limits) {}

std::shared_ptr<const FrameData> FrameLru::find(int frame) {
    const auto entry = findEntry(frame);
    if (entry == entries_.end())
        return nullptr;
    entries_.splice(entries_.begin(), entries_, entry);
    return entry->data;
}

bool FrameLru::contains(int frame) const {
    return findEntry(frame) != entries_.end();
}

void FrameLru::insert(int frame, std::shared_ptr<const FrameData> data) {
    erase(frame);
    const std::size_t size = bytesOf(*data);
    entries_.push_front(Entry{frame, std::move(data), size});
    bytes_ += size;
    evictBeyondLimits();
}

void FrameLru::erase(int frame) {
    const auto entry = findEntry(frame);
    if (entry == entries_.end())
        return;
    bytes_ -= entry->bytes;
    entries_.erase(entry);
}

void FrameLru::clear() {
    entries_.clear();
    bytes_ = 0;
}

std::vector<int> FrameLru::frames() const {
    std::vector<int> result;
    result.reserve(entries_.size());
    for (const Entry& entry : entries_)
        result.push_back(entry.frame);
    return result;
}

std::size_t FrameLru::bytesOf(const FrameData& data) {
    return sizeof(FrameData) + data.state.fluid.allocatedBytes();
}

std::list<FrameLru::Entry>::iterator FrameLru::findEntry(int frame) {
    return std::find_if(entries_.begin(), entries_.end(),
                        [frame](const Entry& entry) { return entry.frame == frame; });
}

std::list<FrameLru::Entry>::const_iterator FrameLru::findEntry(int frame) const {
    return std::find_if(entries_.begin(), entries_.end(),
                        [frame](const Entry& entry) { return entry.frame == frame; });
}

void FrameLru::evictBeyondLimits() {
    const auto overBudget = [this] {
        return entries_.size() > limits_.maxFrames ||
               (bytes_ > limits_.maxBytes && entries_.size() > 1);
    };
    while (!entries_.empty() && overBudget()) {
        bytes_ -= entries_.back().bytes;
        entries_.pop_back();
    }
}

} // namespace airtrap
