#pragma once
// `--frames A:B` of bake and export: "A:B", "A:", ":B" or a single frame "N".
#include <string>
#include <vector>

namespace airtrap::cli {

class FrameRange {
public:
    //! The whole range 1..maxFrame, nothing given.
    explicit FrameRange(int maxFrame) : first_(1), last_(maxFrame) {}

    //! Parses `text` (empty = the whole range). A missing end takes 1 or `maxFrame`. Throws
    //! Error(InvalidInput) naming the option, the value and the allowed range, where
    //! `maxDescription` says where `maxFrame` comes from ("frames.end_frame", "the cache").
    static FrameRange parse(const std::string& text, int maxFrame,
                            const std::string& maxDescription);

    //! The frames of `listed` (ascending) that `text` selects. Refuses an empty `listed` and a
    //! range that holds none of them, naming `where` (the cache folder).
    static std::vector<int> selectListed(const std::vector<int>& listed, const std::string& text,
                                         const std::string& where);

    int first() const { return first_; }
    int last() const { return last_; }
    bool firstGiven() const { return firstGiven_; }
    bool lastGiven() const { return lastGiven_; }
    bool contains(int frame) const { return frame >= first_ && frame <= last_; }

private:
    int first_;
    int last_;
    bool firstGiven_ = false;
    bool lastGiven_ = false;
};

} // namespace airtrap::cli
