#include "bubbles/BubbleImmersion.h"

namespace airtrap {

const std::array<Vec3d, BubbleImmersion::kProbeCount>& BubbleImmersion::directions() {
    static const std::array<Vec3d, kProbeCount> probes = [] {
        std::array<Vec3d, kProbeCount> d;
        int n = 0;
        // The 26 neighbours of a cube's centre, grouped by how many axes they step along: one
        // (faces), two (edges), three (corners).
        for (int axes = 1; axes <= 3; ++axes)
            for (int k = -1; k <= 1; ++k)
                for (int j = -1; j <= 1; ++j)
                    for (int i = -1; i <= 1; ++i)
                        if (std::abs(i) + std::abs(j) + std::abs(k) == axes)
                            d[n++] = Vec3d(i, j, k).normalized();
        return d;
    }();
    return probes;
}

BubbleImmersion::WetProbes BubbleImmersion::hemisphere(const Vec3d& up) {
    WetProbes mask;
    const auto& probes = directions();
    for (int k = 0; k < kProbeCount; ++k)
        if (probes[k].dot(up) > 1e-9)
            mask.set(k);
    return mask;
}

void BubbleImmersion::wetBy(const Vec3d& centre, double radius, const Vec3d& x,
                            WetProbes& wet) const {
    const double probeRadius = radius + 0.5 * spacing_;
    const double wetDistance2 = spacing_ * spacing_;
    const auto& probes = directions();
    for (int k = 0; k < kProbeCount; ++k)
        if ((centre + probeRadius * probes[k] - x).squaredNorm() < wetDistance2)
            wet.set(k);
}

BubbleImmersion::WetProbes BubbleImmersion::measure(const Vec3d& centre, double radius,
                                                    const NeighborGrid& grid,
                                                    const PositionArrays& positions) const {
    WetProbes wet;
    const double reach2 = reach(radius) * reach(radius);
    grid.forEachRangeInBall(centre, reach(radius), [&](std::uint32_t begin, std::uint32_t end) {
        for (std::uint32_t s = begin; s < end; ++s) {
            const Vec3d x = positions[s].cast<double>();
            if ((x - centre).squaredNorm() < reach2)
                wetBy(centre, radius, x, wet);
        }
    });
    return wet;
}

BubbleImmersion::Placement BubbleImmersion::placement(int wetProbes) {
    if (wetProbes >= kInWaterProbes)
        return Placement::InWater;
    return wetProbes < kAirborneBelow ? Placement::Airborne : Placement::Floating;
}

} // namespace airtrap
