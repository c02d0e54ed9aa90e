#include "post/FreeSurface.h"

#include "core/Parallel.h"

#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

constexpr std::uint32_t kDropped = ~std::uint32_t(0);

//! Per vertex: whether it lies within `margin` of a solid or a bubble.
std::vector<char> markNearVertices(const TriangleMesh& water, const FrameSolids& solids,
                                   double margin) {
    std::vector<char> near(water.vertices.size());
    parallelFor(std::size_t(0), water.vertices.size(), [&](std::size_t v) {
        near[v] = solids.clearance(water.vertices[v]) < margin ? 1 : 0;
    });
    return near;
}

//! The way out of the nearest solid or bubble at `x` (the clearance's gradient), unit length;
//! zero where it has none.
Vec3d outOfSolid(const Vec3d& x, const FrameSolids& solids, double step) {
    Vec3d gradient;
    for (int axis = 0; axis < 3; ++axis) {
        const Vec3d offset = step * Vec3d::Unit(axis);
        gradient[axis] = solids.clearance(x + offset) - solids.clearance(x - offset);
    }
    return gradient.squaredNorm() > 0.0 ? Vec3d(gradient.normalized()) : Vec3d::Zero();
}

//! `x` moved along the clearance's gradient onto the nearest solid's or bubble's surface. One step
//! lands on a plane or a sphere; a few more settle a point where two surfaces are about as near,
//! such as a tank's corner, where the gradient averages theirs.
Vec3d ontoSurface(Vec3d x, const FrameSolids& solids, double step) {
    for (int iteration = 0; iteration < 8; ++iteration) {
        const double distance = solids.clearance(x);
        if (std::abs(distance) < step)
            break;
        const Vec3d out = outOfSolid(x, solids, step);
        if (out.isZero())
            break;
        x -= distance * out;
    }
    return x;
}

//! Whether triangle `t` of `water` faces into the solid beside it: the water's outward normal
//! within 60° of the way into it. The water's side against a wall does; its free surface where
//! it meets the wall runs across the way into it and does not.
bool facesTheSolid(const TriangleMesh& water, std::size_t t, const FrameSolids& solids,
                   double step) {
    constexpr double kFacingCosine = 0.5; // cos 60°
    const TriangleMesh::Triangle& triangle = water.triangles[t];
    const Vec3d middle =
        (water.vertices[triangle[0]] + water.vertices[triangle[1]] + water.vertices[triangle[2]]) /
        3.0;
    return water.normal(t).dot(outOfSolid(middle, solids, step)) < -kFacingCosine;
}

//! Per vertex of `mesh`: whether it ends an edge that only one triangle uses.
std::vector<char> openEdgeVertices(const TriangleMesh& mesh) {
    const std::vector<std::uint64_t> edges = mesh.sortedEdgeKeys();
    std::vector<char> open(mesh.vertices.size(), 0);
    for (std::size_t e = 0; e < edges.size();) {
        std::size_t same = e + 1;
        while (same < edges.size() && edges[same] == edges[e])
            ++same;
        if (same - e == 1) {
            open[edges[e] >> 32] = 1;
            open[edges[e] & 0xFFFFFFFFu] = 1;
        }
        e = same;
    }
    return open;
}

} // namespace

TriangleMesh freeSurfaceOnly(const TriangleMesh& water, const FrameSolids& solids, double margin) {
    const std::vector<char> near = markNearVertices(water, solids, margin);
    const double step = 1e-3 * margin;
    std::vector<char> kept(water.triangles.size(), 1);
    parallelFor(std::size_t(0), water.triangles.size(), [&](std::size_t t) {
        const TriangleMesh::Triangle& triangle = water.triangles[t];
        if (near[triangle[0]] && near[triangle[1]] && near[triangle[2]])
            kept[t] = facesTheSolid(water, t, solids, step) ? 0 : 1;
    });
    TriangleMesh trimmed;
    std::vector<std::uint32_t> newIndex(water.vertices.size(), kDropped);
    for (std::size_t t = 0; t < water.triangles.size(); ++t) {
        if (!kept[t])
            continue;
        const TriangleMesh::Triangle& triangle = water.triangles[t];
        trimmed.triangles.push_back(triangle);
        newIndex[triangle[0]] = newIndex[triangle[1]] = newIndex[triangle[2]] = 0;
    }
    for (std::size_t v = 0; v < water.vertices.size(); ++v) {
        if (newIndex[v] == kDropped)
            continue;
        newIndex[v] = std::uint32_t(trimmed.vertices.size());
        trimmed.vertices.push_back(water.vertices[v]);
    }
    for (TriangleMesh::Triangle& t : trimmed.triangles)
        t = {newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]};
    // The edge left where triangles went lies within the margin: moved onto the solid, it meets
    // it with no gap, as the paper's Fig. 2d shows, and no kept polygon reaches inside it. Only
    // that edge moves: the free surface over a bubble just under it stays where it is.
    const std::vector<char> edge = openEdgeVertices(trimmed);
    parallelFor(std::size_t(0), trimmed.vertices.size(), [&](std::size_t v) {
        if (edge[v] && solids.clearance(trimmed.vertices[v]) < margin)
            trimmed.vertices[v] = ontoSurface(trimmed.vertices[v], solids, step);
    });
    return trimmed;
}

TriangleMesh renderedSurface(const TriangleMesh& water, const FrameSolids& solids,
                             const SurfaceMeshSettings& settings, double spacing) {
    if (settings.mode == "closed")
        return water;
    return freeSurfaceOnly(water, solids, settings.margin * spacing);
}

} // namespace airtrap
