#include "scene/InflowNozzle.h"

#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

//! A jet closer to vertical than this has no usable horizontal perpendicular; x is taken.
constexpr double kVerticalTolerance = 1e-6;

//! Lattice coordinates (in spacings) of `count` points centred on 0: ±0.5, ±1.5, … for even
//! counts and 0, ±1, … for odd, the same centring as SceneSetup::fillFluid.
double latticeCoordinate(int index, int count) {
    return index + 0.5 - 0.5 * count;
}

} // namespace

void InflowNozzle::nozzleFrame(const Vec3d& direction, Vec3d& widthAxis, Vec3d& heightAxis) {
    const Vec3d d = direction.normalized();
    const Vec3d horizontal = Vec3d::UnitY().cross(d);
    widthAxis = horizontal.norm() > kVerticalTolerance ? horizontal.normalized() : Vec3d::UnitX();
    heightAxis = d.cross(widthAxis).normalized();
}

Vec3d InflowNozzle::exitHalfExtent(const InflowEmitterSettings& settings) {
    Vec3d widthAxis, heightAxis;
    nozzleFrame(settings.direction, widthAxis, heightAxis);
    if (settings.shape == "rectangle")
        return 0.5 *
               (settings.width * widthAxis.cwiseAbs() + settings.height * heightAxis.cwiseAbs());
    // A disc of radius r spans r·sqrt(1 − d_a²) along axis a.
    const Vec3d d = settings.direction.normalized();
    return settings.radius * (Vec3d::Ones() - d.cwiseProduct(d)).cwiseMax(0.0).cwiseSqrt();
}

InflowNozzle::InflowNozzle(const InflowEmitterSettings& settings, double spacing)
    : settings_(settings), spacing_(spacing), direction_(settings.direction.normalized()) {
    nozzleFrame(settings.direction, widthAxis_, heightAxis_);
    const bool disc = settings.shape == "disc";
    const double width = disc ? 2.0 * settings.radius : settings.width;
    const double height = disc ? 2.0 * settings.radius : settings.height;
    const int nu = std::max(1, static_cast<int>(std::lround(width / spacing)));
    const int nv = std::max(1, static_cast<int>(std::lround(height / spacing)));
    // A lattice point belongs to a disc when its centre is inside; a relative tolerance keeps
    // points exactly on the rim from depending on rounding.
    const double r2 = settings.radius * settings.radius * (1.0 + 1e-9);
    for (int j = 0; j < nv; ++j)
        for (int i = 0; i < nu; ++i) {
            const double u = latticeCoordinate(i, nu) * spacing;
            const double v = latticeCoordinate(j, nv) * spacing;
            if (disc && u * u + v * v > r2)
                continue;
            offsets_.push_back(u * widthAxis_ + v * heightAxis_);
        }
    if (!offsets_.empty())
        layerBudget_ =
            static_cast<std::size_t>(std::max(0, settings.maxParticles)) / offsets_.size();
}

double InflowNozzle::layerTime(std::size_t k) const {
    // A product, never a running sum: the same k gives the same bits whenever it is asked.
    return settings_.startTime + static_cast<double>(k) * (spacing_ / settings_.speed);
}

std::size_t InflowNozzle::layersBefore(double time) const {
    const double end = std::min(time, settings_.stopTime);
    if (end <= settings_.startTime)
        return 0;
    const double period = spacing_ / settings_.speed;
    auto layers = static_cast<std::size_t>(std::ceil((end - settings_.startTime) / period));
    // The division may round across an integer; layerTime() is the definition, so settle on it.
    while (layers > 0 && layerTime(layers - 1) >= end)
        --layers;
    while (layerTime(layers) < end)
        ++layers;
    return std::min(layers, layerBudget_);
}

} // namespace airtrap
