#pragma once
// The ASCII header every PLY file of ours starts with (binary little-endian PLY 1.0, one `vertex`
// element), and the comment-line rule shared by the text formats.
#include <bit>
#include <string>
#include <utility>
#include <vector>

namespace airtrap {

// Bodies are copied as they are in memory, and the header declares them little-endian.
static_assert(std::endian::native == std::endian::little,
              "PLY bodies are written little-endian; a big-endian host needs byte swapping");

//! `text` on one line: a line break inside a header comment would end it early and make the rest
//! a statement the reader does not know.
inline std::string oneLine(std::string text) {
    for (char& c : text)
        if (c == '\n' || c == '\r')
            c = ' ';
    return text;
}

//! "ply … end_header\n" for `count` vertices with `properties` as (type, name) pairs in order.
inline std::string plyHeader(std::size_t count, const std::vector<std::string>& comments,
                             const std::vector<std::pair<const char*, const char*>>& properties) {
    std::string text = "ply\nformat binary_little_endian 1.0\n";
    for (const std::string& comment : comments)
        text += "comment " + oneLine(comment) + "\n";
    text += "element vertex " + std::to_string(count) + "\n";
    for (const auto& [type, name] : properties)
        text += std::string("property ") + type + " " + name + "\n";
    return text + "end_header\n";
}

} // namespace airtrap
