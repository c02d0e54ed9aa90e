#include "rigid/ObjText.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace airtrap {

namespace {

bool isBlank(char c) {
    return c == ' ' || c == '\t';
}

//! Whether `line` (leading blanks skipped) is a vertex, normal or texture-coordinate record.
bool isCoordinateLine(std::string_view line) {
    const auto start = std::find_if_not(line.begin(), line.end(), isBlank);
    const std::string_view rest = line.substr(std::size_t(start - line.begin()));
    for (std::string_view tag : {"v", "vn", "vt"})
        if (rest.size() > tag.size() && rest.substr(0, tag.size()) == tag &&
            isBlank(rest[tag.size()]))
            return true;
    return false;
}

} // namespace

bool ObjText::isObjPath(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return char(std::tolower(c)); });
    return extension == ".obj";
}

std::string ObjText::withLeadingZeros(std::string_view text) {
    std::string out;
    out.reserve(text.size() + text.size() / 16);
    std::size_t start = 0;
    while (start < text.size()) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        appendLine(text.substr(start, end - start), out);
        if (end < text.size())
            out += '\n';
        start = end + 1;
    }
    return out;
}

void ObjText::appendLine(std::string_view line, std::string& out) {
    if (!isCoordinateLine(line)) {
        out += line;
        return;
    }
    for (std::size_t k = 0; k < line.size(); ++k) {
        const bool tokenStart = k == 0 || isBlank(line[k - 1]);
        const bool signBeforePoint =
            (line[k] == '-' || line[k] == '+') && k + 1 < line.size() && line[k + 1] == '.';
        if (tokenStart && signBeforePoint) {
            out += line[k];
            out += '0';
            continue;
        }
        if (tokenStart && line[k] == '.')
            out += '0';
        out += line[k];
    }
}

} // namespace airtrap
