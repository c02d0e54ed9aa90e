#pragma once
// The frames the editor loaded last, kept in memory so that scrubbing back and forth over them
// does not read the disk again. Bounded by a frame count and a byte budget: one large frame may
// weigh hundreds of megabytes.
#include "cache/FrameFile.h"

#include <cstddef>
#include <list>
#include <memory>
#include <vector>

namespace airtrap {

class FrameLru {
public:
    //! How much the LRU keeps.
    struct Limits {
        std::size_t maxFrames = 8;                     //!< frames kept at most
        std::size_t maxBytes = std::size_t(512) << 20; //!< bytesOf() summed, at most
    };

    //! Keeps 8 frames and at most 512 MiB.
    FrameLru();
    explicit FrameLru(Limits limits);

    //! The frame's data, now the most recently used; null when it is not kept.
    std::shared_ptr<const FrameData> find(int frame);
    //! True when the frame is kept, without touching its recency.
    bool contains(int frame) const;
    //! Keeps `data` as the most recently used frame (replacing an older copy), then drops the
    //! least recently used ones beyond the limits. The newest frame is kept even when it alone
    //! exceeds the byte budget: it is the one on screen.
    void insert(int frame, std::shared_ptr<const FrameData> data);
    //! Drops one frame (it changed on disk); nothing when it is not kept.
    void erase(int frame);
    //! Drops every frame.
    void clear();

    //! The kept frames, most recently used first.
    std::vector<int> frames() const;
    //! Number of kept frames.
    std::size_t size() const { return entries_.size(); }
    //! Sum of bytesOf() over the kept frames.
    std::size_t bytes() const { return bytes_; }
    //! The limits given at construction.
    const Limits& limits() const { return limits_; }

    //! Memory a frame's data holds (its arrays' capacity plus the object).
    static std::size_t bytesOf(const FrameData& data);

private:
    struct Entry {
        int frame;
        std::shared_ptr<const FrameData> data;
        std::size_t bytes;
    };
    std::list<Entry>::iterator findEntry(int frame);
    std::list<Entry>::const_iterator findEntry(int frame) const;
    void evictBeyondLimits();

    Limits limits_;
    //! Most recently used first. A list: eight entries make a linear search cheaper than a map.
    std::list<Entry> entries_;
    std::size_t bytes_ = 0;
};

} // namespace airtrap
