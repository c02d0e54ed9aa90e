#include "FrameRange.h"

#include "core/Error.h"

#include <charconv>
#include <optional>

namespace airtrap::cli {

namespace {

//! A whole decimal number and nothing else, or nothing.
std::optional<int> parseFrame(const std::string& text) {
    int value = 0;
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    if (text.empty() || error != std::errc() || stop != end)
        return std::nullopt;
    return value;
}

[[noreturn]] void refuse(const std::string& text, const std::string& why) {
    throw Error(ErrorKind::InvalidInput, "--frames '" + text + "': " + why);
}

} // namespace

FrameRange FrameRange::parse(const std::string& text, int maxFrame,
                             const std::string& maxDescription) {
    FrameRange range(maxFrame);
    if (text.empty())
        return range;
    const std::size_t colon = text.find(':');
    const std::string firstText = text.substr(0, colon);
    const std::string lastText = colon == std::string::npos ? firstText : text.substr(colon + 1);
    if (firstText.empty() && lastText.empty())
        refuse(text, "expected A:B, A:, :B or N");
    for (const std::string* part : {&firstText, &lastText})
        if (!part->empty() && !parseFrame(*part))
            refuse(text, "'" + *part + "' is not a frame number; expected A:B, A:, :B or N");
    range.firstGiven_ = !firstText.empty();
    range.lastGiven_ = !lastText.empty();
    if (range.firstGiven_)
        range.first_ = *parseFrame(firstText);
    if (range.lastGiven_)
        range.last_ = *parseFrame(lastText);
    const std::string allowed =
        "frames run from 1 to " + std::to_string(maxFrame) + " (" + maxDescription + ")";
    if (range.first_ < 1 || range.first_ > maxFrame || range.last_ < 1 || range.last_ > maxFrame)
        refuse(text, "out of range: " + allowed);
    if (range.first_ > range.last_)
        refuse(text, "the first frame (" + std::to_string(range.first_) +
                         ") comes after the last (" + std::to_string(range.last_) + ")");
    return range;
}

std::vector<int> FrameRange::selectListed(const std::vector<int>& listed, const std::string& text,
                                          const std::string& where) {
    if (listed.empty())
        throw Error(ErrorKind::InvalidInput, where + " holds no frames yet");
    const FrameRange range = parse(text, listed.back(), "the last frame in " + where);
    std::vector<int> selected;
    for (const int frame : listed)
        if (range.contains(frame))
            selected.push_back(frame);
    if (selected.empty())
        throw Error(ErrorKind::InvalidInput,
                    "--frames " + text + ": " + where + " holds none of these frames");
    return selected;
}

} // namespace airtrap::cli
