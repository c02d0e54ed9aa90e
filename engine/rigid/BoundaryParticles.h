#pragma once
// One layer of boundary particles on a body's surface, in the body's local frame (Akinci et al.
// 2012: one layer suffices and sampling may be non-uniform). Moving the body moves them rigidly.
#include "core/Math.h"

#include <vector>

namespace airtrap {

struct BoundaryParticles {
    std::vector<Vec3f> positions; //!< body-local, m
    std::vector<Vec3f> normals;   //!< body-local unit normals, pointing into the water
    std::vector<float> volumes;   //!< m³, V_b = 1 / Σ_k W_bk over the body's own particles

    std::size_t size() const { return positions.size(); }
};

} // namespace airtrap
