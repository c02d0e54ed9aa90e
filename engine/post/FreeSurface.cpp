#include "post/FreeSurface.h"

#include <tbb/parallel_for.h>

namespace airtrap {

namespace {

constexpr std::uint32_t kDropped = ~std::uint32_t(0);

//! Per vertex: its index in the trimmed mesh, or kDropped when it is too close to a solid.
std::vector<std::uint32_t> markClearVertices(const TriangleMesh& water, const FrameSolids& solids,
                                             double margin) {
    std::vector<std::uint32_t> kept(water.vertices.size());
    tbb::parallel_for(std::size_t(0), water.vertices.size(), [&](std::size_t v) {
        kept[v] = solids.clearance(water.vertices[v]) >= margin ? 0 : kDropped;
    });
    return kept;
}

} // namespace

TriangleMesh freeSurfaceOnly(const TriangleMesh& water, const FrameSolids& solids, double margin) {
    std::vector<std::uint32_t> newIndex = markClearVertices(water, solids, margin);
    std::vector<bool> used(water.vertices.size(), false);
    TriangleMesh trimmed;
    for (const TriangleMesh::Triangle& t : water.triangles) {
        if (newIndex[t[0]] == kDropped || newIndex[t[1]] == kDropped || newIndex[t[2]] == kDropped)
            continue;
        trimmed.triangles.push_back(t);
        used[t[0]] = used[t[1]] = used[t[2]] = true;
    }
    for (std::size_t v = 0; v < water.vertices.size(); ++v) {
        if (!used[v])
            continue;
        newIndex[v] = std::uint32_t(trimmed.vertices.size());
        trimmed.vertices.push_back(water.vertices[v]);
    }
    for (TriangleMesh::Triangle& t : trimmed.triangles)
        t = {newIndex[t[0]], newIndex[t[1]], newIndex[t[2]]};
    return trimmed;
}

} // namespace airtrap
