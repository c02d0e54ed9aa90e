#include "rigid/ObjText.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <vector>

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

std::vector<std::string_view> tokensOf(std::string_view line) {
    std::vector<std::string_view> tokens;
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && (isBlank(line[k]) || line[k] == '\r'))
            ++k;
        const std::size_t start = k;
        while (k < line.size() && !isBlank(line[k]) && line[k] != '\r')
            ++k;
        if (k > start)
            tokens.push_back(line.substr(start, k - start));
    }
    return tokens;
}

bool isNumber(std::string_view token) {
    const std::string text(token);
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    return end == text.c_str() + text.size() && std::isfinite(value);
}

//! "12", "12/3", "12/3/4", "12//4": the vertex index before the first slash.
bool vertexIndexOf(std::string_view token, long long& index) {
    const std::string_view digits = token.substr(0, token.find('/'));
    const auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), index);
    return error == std::errc() && end == digits.data() + digits.size() && index != 0;
}

} // namespace

std::string ObjText::problemIn(std::string_view text) {
    long long vertices = 0;
    long long lineNumber = 1;
    for (std::size_t start = 0; start < text.size(); ++lineNumber) {
        const std::size_t end = std::min(text.find('\n', start), text.size());
        const std::vector<std::string_view> tokens = tokensOf(text.substr(start, end - start));
        if (std::string problem = problemInLine(tokens, vertices); !problem.empty())
            return "line " + std::to_string(lineNumber) + ": " + problem;
        vertices += !tokens.empty() && tokens.front() == "v";
        start = end + 1;
    }
    return {};
}

std::string ObjText::problemInLine(const std::vector<std::string_view>& tokens,
                                   long long vertices) {
    if (tokens.empty())
        return {};
    const std::string_view tag = tokens.front();
    if (tag == "v" || tag == "vn" || tag == "vt") {
        for (std::size_t k = 1; k < tokens.size(); ++k)
            if (!isNumber(tokens[k]))
                return std::string(tag) + " value '" + std::string(tokens[k]) + "' is not a number";
        if (tag == "v" && tokens.size() < 4)
            return "a vertex needs 3 coordinates, this one has " +
                   std::to_string(tokens.size() - 1);
    }
    if (tag != "f")
        return {};
    for (std::size_t k = 1; k < tokens.size(); ++k) {
        long long index = 0;
        if (!vertexIndexOf(tokens[k], index))
            return "face corner '" + std::string(tokens[k]) + "' has no vertex index";
        // Negative indices count back from the last vertex defined.
        if (index > vertices || -index > vertices)
            return "the face refers to vertex " + std::to_string(index) + ", but " +
                   std::to_string(vertices) + " are defined before it";
    }
    return {};
}

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
