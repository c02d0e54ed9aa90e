#pragma once
// An indexed triangle mesh in a body's frame: the shape of a mesh rigid body, before it becomes
// mass properties, a signed distance field and boundary particles.
#include "core/Math.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace airtrap {

struct TriangleMesh {
    using Triangle = std::array<std::uint32_t, 3>;

    //! How a mesh's edges are shared; a closed, consistently oriented surface has only
    //! `paired` edges (each used once in each direction by two triangles).
    struct EdgeCounts {
        std::size_t paired = 0;      //!< shared by two triangles in opposite directions
        std::size_t open = 0;        //!< belong to only one triangle: a hole's rim
        std::size_t nonManifold = 0; //!< belong to more than two triangles
        std::size_t misoriented = 0; //!< two triangles use them in the same direction
    };

    std::vector<Vec3d> vertices;     //!< m
    std::vector<Triangle> triangles; //!< vertex indices, counter-clockwise seen from outside

    std::size_t triangleCount() const { return triangles.size(); }
    Aabb bounds() const;

    //! Unnormalised normal of triangle `t`: its length is twice the area, m².
    Vec3d areaVector(std::size_t t) const;
    //! Unit normal per vertex: the sum of its triangles' area vectors, normalised (zero for a
    //! vertex no triangle uses); what smooth shading and the OBJ export's `vn` lines use.
    std::vector<Vec3d> vertexNormals() const;
    //! Unit normal of triangle `t` (zero for a degenerate triangle).
    Vec3d normal(std::size_t t) const;
    double area(std::size_t t) const;
    double surfaceArea() const; //!< m²

    //! Volume enclosed, m³; positive when the triangles face outward, negative when the mesh is
    //! inside-out. Only meaningful for a closed mesh.
    double signedVolume() const;

    EdgeCounts countEdges() const;
    //! One key per undirected edge: the lower vertex index in the high 32 bits, the higher below.
    static std::uint64_t edgeKey(std::uint32_t a, std::uint32_t b) {
        return std::uint64_t(std::min(a, b)) << 32 | std::max(a, b);
    }
    //! The edge keys of every triangle, three each, sorted: an edge that k triangles share
    //! appears k times in a row.
    std::vector<std::uint64_t> sortedEdgeKeys() const;

    //! Reverses every triangle's winding, which turns its normal around.
    void flipOrientation();

    //! x ↦ rotation · (scale · x) + translation, applied to every vertex.
    TriangleMesh transformed(double scale, const Quatd& rotation = Quatd::Identity(),
                             const Vec3d& translation = Vec3d::Zero()) const;
};

} // namespace airtrap
