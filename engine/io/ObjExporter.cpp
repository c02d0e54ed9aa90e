#include "io/ObjExporter.h"

#include "core/AtomicFile.h"
#include "io/PlyHeader.h"

#include <charconv>
#include <string>
#include <string_view>

namespace airtrap {

namespace {

//! Appends " x y z" with the shortest decimals that read back to the same floats: a tenth of a
//! millimetre survives at a kilometre, and the file stays small.
void appendTriple(std::string& text, const Vec3d& v) {
    char buffer[64];
    for (int axis = 0; axis < 3; ++axis) {
        buffer[0] = ' ';
        const auto result = std::to_chars(buffer + 1, buffer + sizeof buffer, float(v[axis]));
        text.append(buffer, result.ptr);
    }
    text += '\n';
}

std::string objectName(const std::string& name) {
    // A name is one token to most readers; spaces would split it.
    std::string token = name.empty() ? std::string("object") : name;
    for (char& c : token)
        if (c == ' ' || c == '\t' || c == '\n' || c == '\r')
            c = '_';
    return token;
}

void appendObject(std::string& text, const NamedMesh& object, UpAxis up, std::size_t firstVertex) {
    text += "o " + objectName(object.name) + "\n";
    for (const Vec3d& v : object.mesh.vertices) {
        text += 'v';
        appendTriple(text, toExportAxes(v, up));
    }
    for (const Vec3d& n : object.mesh.vertexNormals()) {
        text += "vn";
        appendTriple(text, toExportAxes(n, up));
    }
    char buffer[32];
    for (const TriangleMesh::Triangle& t : object.mesh.triangles) {
        text += 'f';
        for (const std::uint32_t index : t) {
            // OBJ counts from 1, across the whole file.
            const auto end = std::to_chars(buffer, buffer + sizeof buffer, firstVertex + index + 1);
            const std::string_view number(buffer, std::size_t(end.ptr - buffer));
            text += ' ';
            text += number;
            text += "//";
            text += number;
        }
        text += '\n';
    }
}

} // namespace

std::string ObjExporter::encode(const std::vector<NamedMesh>& objects, UpAxis up,
                                const std::vector<std::string>& comments) {
    std::string text;
    for (const std::string& comment : comments)
        text += "# " + oneLine(comment) + "\n";
    std::size_t firstVertex = 0;
    std::size_t triangles = 0;
    for (const NamedMesh& object : objects) {
        appendObject(text, object, up, firstVertex);
        firstVertex += object.mesh.vertices.size();
        triangles += object.mesh.triangles.size();
    }
    // Importers read a cut-off file without a word; this last line tells a reader that the file
    // is whole and what it holds (the Blender add-on checks it, docs/BLENDER.md).
    text += "# end: " + std::to_string(firstVertex) + " vertices, " + std::to_string(triangles) +
            " triangles\n";
    return text;
}

void ObjExporter::write(const std::string& path, const std::vector<NamedMesh>& objects, UpAxis up,
                        const std::vector<std::string>& comments) {
    AtomicFile::write(path, encode(objects, up, comments));
}

} // namespace airtrap
