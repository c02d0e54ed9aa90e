#include "post/Icosphere.h"

#include "core/Error.h"

#include <cmath>
#include <map>
#include <utility>

namespace airtrap {

namespace {

TriangleMesh icosahedron() {
    const double phi = 0.5 * (1.0 + std::sqrt(5.0));
    TriangleMesh mesh;
    for (const Vec3d& v :
         {Vec3d(-1, phi, 0), Vec3d(1, phi, 0), Vec3d(-1, -phi, 0), Vec3d(1, -phi, 0),
          Vec3d(0, -1, phi), Vec3d(0, 1, phi), Vec3d(0, -1, -phi), Vec3d(0, 1, -phi),
          Vec3d(phi, 0, -1), Vec3d(phi, 0, 1), Vec3d(-phi, 0, -1), Vec3d(-phi, 0, 1)})
        mesh.vertices.push_back(v.normalized());
    mesh.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                      {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                      {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                      {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    return mesh;
}

//! Splits every triangle into four through its edges' midpoints, lifted onto the sphere; a
//! shared edge gets one midpoint, so the surface stays closed.
TriangleMesh subdivided(const TriangleMesh& mesh) {
    TriangleMesh finer;
    finer.vertices = mesh.vertices;
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        const auto [found, added] =
            midpoints.try_emplace(key, static_cast<std::uint32_t>(finer.vertices.size()));
        if (added)
            finer.vertices.push_back((mesh.vertices[a] + mesh.vertices[b]).normalized());
        return found->second;
    };
    for (const TriangleMesh::Triangle& t : mesh.triangles) {
        const std::uint32_t ab = midpoint(t[0], t[1]);
        const std::uint32_t bc = midpoint(t[1], t[2]);
        const std::uint32_t ca = midpoint(t[2], t[0]);
        finer.triangles.push_back({t[0], ab, ca});
        finer.triangles.push_back({t[1], bc, ab});
        finer.triangles.push_back({t[2], ca, bc});
        finer.triangles.push_back({ab, bc, ca});
    }
    return finer;
}

} // namespace

TriangleMesh unitIcosphere(int subdivisions) {
    if (subdivisions < 0 || subdivisions > 6)
        throw Error(ErrorKind::InvalidInput, "icosphere subdivisions " +
                                                 std::to_string(subdivisions) +
                                                 " out of range; expected 0 to 6");
    TriangleMesh mesh = icosahedron();
    for (int level = 0; level < subdivisions; ++level)
        mesh = subdivided(mesh);
    return mesh;
}

} // namespace airtrap
