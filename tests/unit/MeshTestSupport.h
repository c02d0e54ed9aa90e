#pragma once
// Meshes made in code for the rigid-geometry tests, and writers for the file formats the loader
// must read, so each test knows its mesh exactly.
#include "post/Icosphere.h"
#include "rigid/TriangleMesh.h"

#include <QString>
#include <cmath>
#include <fstream>
#include <limits>
#include <utility>

namespace airtrap::test {

//! Icosahedron subdivided `levels` times, vertices pushed onto the sphere: 20·4^levels outward
//! triangles (3 levels: 1280).
inline TriangleMesh icosphere(double radius, int levels) {
    return unitIcosphere(levels).transformed(radius);
}

//! Cube of edge `edge` centred at the origin, 12 outward triangles.
inline TriangleMesh cube(double edge) {
    TriangleMesh mesh;
    for (int corner = 0; corner < 8; ++corner)
        mesh.vertices.push_back(
            0.5 * edge * Vec3d(corner & 1 ? 1 : -1, corner & 2 ? 1 : -1, corner & 4 ? 1 : -1));
    // Corner index bits are (x, y, z); each face is two triangles counter-clockwise from outside.
    mesh.triangles = {{0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}, {0, 1, 5}, {0, 5, 4},
                      {2, 6, 7}, {2, 7, 3}, {0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}};
    return mesh;
}

inline void writeObj(const QString& path, const TriangleMesh& mesh) {
    std::ofstream out(path.toStdString());
    out.precision(17);
    for (const Vec3d& v : mesh.vertices)
        out << "v " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& [a, b, c] : mesh.triangles)
        out << "f " << a + 1 << ' ' << b + 1 << ' ' << c + 1 << '\n';
}

//! ASCII STL: a soup of triangles, each with its own copy of its corners.
inline void writeStl(const QString& path, const TriangleMesh& mesh) {
    std::ofstream out(path.toStdString());
    out.precision(9);
    out << "solid test\n";
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        const Vec3d n = mesh.normal(t);
        out << "facet normal " << n.x() << ' ' << n.y() << ' ' << n.z() << "\n outer loop\n";
        for (std::uint32_t index : mesh.triangles[t]) {
            const Vec3d& v = mesh.vertices[index];
            out << "  vertex " << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
        }
        out << " endloop\nendfacet\n";
    }
    out << "endsolid test\n";
}

inline void writePly(const QString& path, const TriangleMesh& mesh) {
    std::ofstream out(path.toStdString());
    out.precision(9);
    out << "ply\nformat ascii 1.0\nelement vertex " << mesh.vertices.size()
        << "\nproperty float x\nproperty float y\nproperty float z\nelement face "
        << mesh.triangleCount() << "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const Vec3d& v : mesh.vertices)
        out << v.x() << ' ' << v.y() << ' ' << v.z() << '\n';
    for (const auto& [a, b, c] : mesh.triangles)
        out << "3 " << a << ' ' << b << ' ' << c << '\n';
}

//! Distance from each point to its nearest other point (brute force: the tests' sets are small).
inline std::vector<double> nearestNeighbourDistances(const std::vector<Vec3f>& points) {
    std::vector<double> nearest(points.size(), std::numeric_limits<double>::infinity());
    for (std::size_t a = 0; a < points.size(); ++a)
        for (std::size_t b = a + 1; b < points.size(); ++b) {
            const double d = (points[a] - points[b]).cast<double>().norm();
            nearest[a] = std::min(nearest[a], d);
            nearest[b] = std::min(nearest[b], d);
        }
    return nearest;
}

//! Share of `values` within [low, high].
inline double fractionWithin(const std::vector<double>& values, double low, double high) {
    std::size_t inside = 0;
    for (double v : values)
        inside += (v >= low && v <= high) ? 1 : 0;
    return values.empty() ? 0.0 : double(inside) / double(values.size());
}

//! Relative difference, for checks stated as a percentage.
inline double relativeError(double value, double expected) {
    return std::abs(value - expected) / std::abs(expected);
}

} // namespace airtrap::test
