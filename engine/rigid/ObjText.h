#pragma once
// OBJ text as assimp 5.2 reads it. Its OBJ parser takes a coordinate written without a digit
// before the point (".1", "-.5", valid in OBJ and common in exported files) for the end of the
// line, and the faces then point past the vertices read ("vertex index out of range").
#include <string>
#include <string_view>
#include <vector>

namespace airtrap {

class ObjText {
public:
    //! Whether `path` names an OBJ file (by its extension, any case).
    static bool isObjPath(const std::string& path);
    //! `text` with a 0 before every number of a v, vn or vt line that starts with its point
    //! (".1" → "0.1", "-.5" → "-0.5"); every other byte as it was.
    static std::string withLeadingZeros(std::string_view text);

    //! The first thing in `text` assimp's OBJ parser would trip on, as "line N: …", or empty: a
    //! v, vn or vt value that is not a number, a v line with fewer than 3, a face index that is
    //! not an integer or names a vertex not defined before it. assimp 5.2 reports such a file as
    //! "vertex index out of range" and leaks the mesh it was building (found by the fuzzer), so
    //! the file is refused before assimp reads it.
    static std::string problemIn(std::string_view text);

private:
    //! One line, its numbers given their leading zero when it is a v, vn or vt line.
    static void appendLine(std::string_view line, std::string& out);
    //! What is wrong with one line (its blank-separated tokens), given how many vertices the
    //! lines before it defined.
    static std::string problemInLine(const std::vector<std::string_view>& tokens,
                                     long long vertices);
};

} // namespace airtrap
