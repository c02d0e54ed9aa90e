#pragma once
// The water's velocity anywhere, interpolated from a cached frame's particles: the Shepard-
// normalised SPH average Σ v_j W_j / Σ W_j over the particles within the kernel's support
// (docs/METHOD.md "Sub-grid bubbles"). Particles are binned once into a hashed grid of
// support-sized cells, so a query visits 27 cells.
#include "sph/ParticleSet.h"

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace airtrap {

class WaterVelocityField {
public:
    //! Keeps a reference to `fluid`, which must outlive the field.
    WaterVelocityField(const ParticleSet& fluid, double supportRadius);

    struct Sample {
        Vec3d velocity = Vec3d::Zero(); //!< m/s; zero where there is no water
        double weight = 0.0; //!< Σ W_j V₀ over the neighbours: about 1 inside water, 0 in air
    };
    //! `volume` is a particle's rest volume (spacing³), so that `weight` reads as a water fraction.
    Sample sample(const Vec3d& x, double volume) const;

private:
    std::int64_t key(const Vec3i& cell) const;
    Vec3i cellOf(const Vec3d& x) const;
    double kernel(double r) const;

    const ParticleSet& fluid_;
    double support_;
    std::unordered_map<std::int64_t, std::vector<std::uint32_t>> cells_;
};

} // namespace airtrap
