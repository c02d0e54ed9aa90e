#include "post/ShapeTessellation.h"

#include "post/Icosphere.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace airtrap {

namespace {

//! Appends the quad a b c d (counter-clockwise seen from outside) with vertices of its own.
void addQuad(TriangleMesh& mesh, const Vec3d& a, const Vec3d& b, const Vec3d& c, const Vec3d& d) {
    const auto first = std::uint32_t(mesh.vertices.size());
    mesh.vertices.insert(mesh.vertices.end(), {a, b, c, d});
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.triangles.push_back({first, first + 2, first + 3});
}

//! A disc of `rim` points around `centre`, facing along the rim's winding (counter-clockwise
//! seen from the side it faces).
void addCap(TriangleMesh& mesh, const Vec3d& centre, const std::vector<Vec3d>& rim) {
    const auto middle = std::uint32_t(mesh.vertices.size());
    mesh.vertices.push_back(centre);
    mesh.vertices.insert(mesh.vertices.end(), rim.begin(), rim.end());
    const auto count = std::uint32_t(rim.size());
    for (std::uint32_t i = 0; i < count; ++i)
        mesh.triangles.push_back({middle, middle + 1 + i, middle + 1 + (i + 1) % count});
}

} // namespace

TriangleMesh tessellateBox(const Vec3d& size) {
    const Vec3d h = 0.5 * size;
    const auto corner = [&h](int x, int y, int z) {
        return Vec3d(x ? h.x() : -h.x(), y ? h.y() : -h.y(), z ? h.z() : -h.z());
    };
    TriangleMesh mesh;
    addQuad(mesh, corner(1, 0, 0), corner(1, 1, 0), corner(1, 1, 1), corner(1, 0, 1)); // +x
    addQuad(mesh, corner(0, 0, 0), corner(0, 0, 1), corner(0, 1, 1), corner(0, 1, 0)); // −x
    addQuad(mesh, corner(0, 1, 0), corner(0, 1, 1), corner(1, 1, 1), corner(1, 1, 0)); // +y
    addQuad(mesh, corner(0, 0, 0), corner(1, 0, 0), corner(1, 0, 1), corner(0, 0, 1)); // −y
    addQuad(mesh, corner(0, 0, 1), corner(1, 0, 1), corner(1, 1, 1), corner(0, 1, 1)); // +z
    addQuad(mesh, corner(0, 0, 0), corner(0, 1, 0), corner(1, 1, 0), corner(1, 0, 0)); // −z
    return mesh;
}

TriangleMesh tessellateSphere(double radius) {
    constexpr int kSubdivisions = 3;
    return unitIcosphere(kSubdivisions).transformed(radius);
}

TriangleMesh tessellateCylinder(double radius, double height, int segments) {
    segments = std::max(segments, 3);
    const double top = 0.5 * height;
    std::vector<Vec3d> lower;
    std::vector<Vec3d> upper;
    for (int i = 0; i < segments; ++i) {
        // From +x toward +z: the order in which a cap faces down.
        const double angle = 2.0 * kPi * i / segments;
        const double x = radius * std::cos(angle);
        const double z = radius * std::sin(angle);
        lower.emplace_back(x, -top, z);
        upper.emplace_back(x, top, z);
    }
    TriangleMesh mesh;
    addCap(mesh, Vec3d(0.0, -top, 0.0), lower);
    std::reverse(upper.begin(), upper.end());
    addCap(mesh, Vec3d(0.0, top, 0.0), upper);
    std::reverse(upper.begin(), upper.end());
    for (int i = 0; i < segments; ++i) {
        const int next = (i + 1) % segments;
        addQuad(mesh, lower[i], upper[i], upper[next], lower[next]);
    }
    return mesh;
}

} // namespace airtrap
