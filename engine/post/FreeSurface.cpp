#include "post/FreeSurface.h"

#include <cmath>
#include <tbb/parallel_for.h>

namespace airtrap {

namespace {

constexpr std::uint32_t kDropped = ~std::uint32_t(0);

//! Per vertex: whether it lies within `margin` of a solid or a bubble.
std::vector<char> markNearVertices(const TriangleMesh& water, const FrameSolids& solids,
                                   double margin) {
    std::vector<char> near(water.vertices.size());
    tbb::parallel_for(std::size_t(0), water.vertices.size(), [&](std::size_t v) {
        near[v] = solids.clearance(water.vertices[v]) < margin ? 1 : 0;
    });
    return near;
}

//! `x` moved along the clearance's gradient onto the nearest solid's or bubble's surface. One step
//! lands on a plane or a sphere; a few more settle a point where two surfaces are about as near,
//! such as a tank's corner, where the gradient averages theirs.
Vec3d ontoSurface(Vec3d x, const FrameSolids& solids, double step) {
    for (int iteration = 0; iteration < 8; ++iteration) {
        const double distance = solids.clearance(x);
        if (std::abs(distance) < step)
            break;
        Vec3d gradient;
        for (int axis = 0; axis < 3; ++axis) {
            const Vec3d offset = step * Vec3d::Unit(axis);
            gradient[axis] = solids.clearance(x + offset) - solids.clearance(x - offset);
        }
        if (gradient.squaredNorm() == 0.0)
            break;
        x -= distance * gradient.normalized();
    }
    return x;
}

} // namespace

TriangleMesh freeSurfaceOnly(const TriangleMesh& water, const FrameSolids& solids, double margin) {
    const std::vector<char> near = markNearVertices(water, solids, margin);
    std::vector<std::uint32_t> newIndex(water.vertices.size(), kDropped);
    TriangleMesh trimmed;
    for (const TriangleMesh::Triangle& t : water.triangles) {
        if (near[t[0]] && near[t[1]] && near[t[2]])
            continue; // along the other surface
        trimmed.triangles.push_back(t);
        newIndex[t[0]] = newIndex[t[1]] = newIndex[t[2]] = 0;
    }
    for (std::size_t v = 0; v < water.vertices.size(); ++v) {
        if (newIndex[v] == kDropped)
            continue;
        newIndex[v] = std::uint32_t(trimmed.vertices.size());
        trimmed.vertices.push_back(water.vertices[v]);
    }
    // The edge left where triangles went lies within the margin: moved onto the solid, it meets
    // it with no gap, as the paper's Fig. 2d shows, and no kept polygon reaches inside it.
    const double step = 1e-3 * margin;
    tbb::parallel_for(std::size_t(0), water.vertices.size(), [&](std::size_t v) {
        if (newIndex[v] != kDropped && near[v])
            trimmed.vertices[newIndex[v]] = ontoSurface(water.vertices[v], solids, step);
    });
    for (TriangleMesh::Triangle& t : trimmed.triangles)
        t = {newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]};
    return trimmed;
}

TriangleMesh renderedSurface(const TriangleMesh& water, const FrameSolids& solids,
                             const SurfaceMeshSettings& settings, double spacing) {
    if (settings.mode == "closed")
        return water;
    return freeSurfaceOnly(water, solids, settings.margin * spacing);
}

} // namespace airtrap
