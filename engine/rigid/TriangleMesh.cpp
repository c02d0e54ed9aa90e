#include "rigid/TriangleMesh.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace airtrap {

Aabb TriangleMesh::bounds() const {
    if (vertices.empty())
        return {};
    Aabb box{vertices[0], vertices[0]};
    for (const Vec3d& v : vertices) {
        box.min = box.min.cwiseMin(v);
        box.max = box.max.cwiseMax(v);
    }
    return box;
}

std::vector<Vec3d> TriangleMesh::vertexNormals() const {
    std::vector<Vec3d> normals(vertices.size(), Vec3d::Zero());
    for (std::size_t t = 0; t < triangleCount(); ++t)
        for (const std::uint32_t v : triangles[t])
            normals[v] += areaVector(t);
    for (Vec3d& n : normals)
        if (n.squaredNorm() > 0.0)
            n.normalize();
    return normals;
}

Vec3d TriangleMesh::areaVector(std::size_t t) const {
    const Triangle& tri = triangles[t];
    const Vec3d& a = vertices[tri[0]];
    return (vertices[tri[1]] - a).cross(vertices[tri[2]] - a);
}

Vec3d TriangleMesh::normal(std::size_t t) const {
    const Vec3d n = areaVector(t);
    const double length = n.norm();
    return length > 0.0 ? Vec3d(n / length) : Vec3d::Zero();
}

double TriangleMesh::area(std::size_t t) const {
    return 0.5 * areaVector(t).norm();
}

double TriangleMesh::surfaceArea() const {
    double sum = 0.0;
    for (std::size_t t = 0; t < triangles.size(); ++t)
        sum += area(t);
    return sum;
}

double TriangleMesh::signedVolume() const {
    // Divergence theorem: each triangle and a reference point span a signed tetrahedron of volume
    // a·(b × c)/6. Measuring from the box centre rather than the origin keeps the sum free of
    // cancellation for a mesh placed far from the origin.
    const Vec3d reference = bounds().center();
    double sixVolume = 0.0;
    for (const Triangle& tri : triangles) {
        const Vec3d a = vertices[tri[0]] - reference;
        const Vec3d b = vertices[tri[1]] - reference;
        const Vec3d c = vertices[tri[2]] - reference;
        sixVolume += a.dot(b.cross(c));
    }
    return sixVolume / 6.0;
}

TriangleMesh::EdgeCounts TriangleMesh::countEdges() const {
    // Per undirected edge (low, high): how often it is walked low → high and high → low.
    std::unordered_map<std::uint64_t, std::pair<int, int>> uses;
    uses.reserve(triangles.size() * 2);
    for (const Triangle& tri : triangles)
        for (int corner = 0; corner < 3; ++corner) {
            const std::uint32_t from = tri[corner];
            const std::uint32_t to = tri[(corner + 1) % 3];
            auto& [upward, downward] = uses[edgeKey(from, to)];
            (from < to ? upward : downward) += 1;
        }
    EdgeCounts counts;
    for (const auto& [key, directions] : uses) {
        const auto [upward, downward] = directions;
        if (upward + downward == 1)
            ++counts.open;
        else if (upward + downward > 2)
            ++counts.nonManifold;
        else if (upward == 2 || downward == 2)
            ++counts.misoriented;
        else
            ++counts.paired;
    }
    return counts;
}

std::vector<std::uint64_t> TriangleMesh::sortedEdgeKeys() const {
    std::vector<std::uint64_t> keys;
    keys.reserve(3 * triangles.size());
    for (const Triangle& tri : triangles)
        for (int corner = 0; corner < 3; ++corner)
            keys.push_back(edgeKey(tri[corner], tri[(corner + 1) % 3]));
    std::sort(keys.begin(), keys.end());
    return keys;
}

void TriangleMesh::flipOrientation() {
    for (Triangle& tri : triangles)
        std::swap(tri[1], tri[2]);
}

TriangleMesh TriangleMesh::transformed(double scale, const Quatd& rotation,
                                       const Vec3d& translation) const {
    TriangleMesh out;
    out.triangles = triangles;
    out.vertices.reserve(vertices.size());
    for (const Vec3d& v : vertices)
        out.vertices.push_back(rotation * (scale * v) + translation);
    if (scale < 0.0)
        out.flipOrientation(); // a mirror turns the surface inside-out
    return out;
}

} // namespace airtrap
