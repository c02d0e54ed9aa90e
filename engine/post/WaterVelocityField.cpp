#include "post/WaterVelocityField.h"

#include <cmath>

namespace airtrap {

WaterVelocityField::WaterVelocityField(const ParticleSet& fluid, double supportRadius)
    : fluid_(fluid), support_(supportRadius) {
    for (std::size_t n = 0; n < fluid.size(); ++n)
        cells_[key(cellOf(fluid.positions[n].cast<double>()))].push_back(std::uint32_t(n));
}

std::int64_t WaterVelocityField::key(const Vec3i& cell) const {
    // 21 bits per axis: ±a million cells, far beyond any domain at any spacing.
    constexpr std::int64_t kMask = (1 << 21) - 1;
    return ((std::int64_t(cell.x()) & kMask) << 42) | ((std::int64_t(cell.y()) & kMask) << 21) |
           (std::int64_t(cell.z()) & kMask);
}

Vec3i WaterVelocityField::cellOf(const Vec3d& x) const {
    return (x / support_).array().floor().cast<int>();
}

double WaterVelocityField::kernel(double r) const {
    // The cubic spline with support H = 2h, normalised in 3D (σ = 1/(πh³)), as the solver's.
    const double h = 0.5 * support_;
    const double q = r / h;
    const double sigma = 1.0 / (kPi * h * h * h);
    if (q < 1.0)
        return sigma * (1.0 - 1.5 * q * q + 0.75 * q * q * q);
    if (q < 2.0)
        return sigma * 0.25 * std::pow(2.0 - q, 3);
    return 0.0;
}

WaterVelocityField::Sample WaterVelocityField::sample(const Vec3d& x, double volume) const {
    const Vec3i centre = cellOf(x);
    Vec3d weighted = Vec3d::Zero();
    double total = 0.0;
    for (int dx = -1; dx <= 1; ++dx)
        for (int dy = -1; dy <= 1; ++dy)
            for (int dz = -1; dz <= 1; ++dz) {
                const auto found = cells_.find(key(centre + Vec3i(dx, dy, dz)));
                if (found == cells_.end())
                    continue;
                for (const std::uint32_t n : found->second) {
                    const double w = kernel((fluid_.positions[n].cast<double>() - x).norm());
                    weighted += w * fluid_.velocities[n].cast<double>();
                    total += w;
                }
            }
    Sample result;
    if (total > 0.0)
        result.velocity = weighted / total;
    result.weight = total * volume;
    return result;
}

} // namespace airtrap
