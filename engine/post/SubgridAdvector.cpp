#include "post/SubgridAdvector.h"

#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {
//! Water fraction below which a point is in air: half a particle's worth of water.
constexpr double kInWater = 0.5;
} // namespace

SubgridAdvector::SubgridAdvector(const SubgridBubbleSettings& settings, const Scene& scene)
    : settings_(settings), rise_(scene.bubbles), up_(-scene.solver.gravity.normalized()),
      gravity_(scene.solver.gravity.norm()),
      particleVolume_(std::pow(scene.solver.particleSpacing, 3)), support_(scene.supportRadius()) {}

double SubgridAdvector::riseSpeed(double radius) const {
    const double stokes = 2.0 / 9.0 * gravity_ * radius * radius / rise_.kinematicViscosity;
    return std::min(stokes, rise_.maxRiseSpeed);
}

bool SubgridAdvector::besideTrappedBubble(const Vec3d& x,
                                          const std::vector<BubbleState>& trapped) const {
    return std::any_of(trapped.begin(), trapped.end(), [&](const BubbleState& bubble) {
        return (x - bubble.body.position).norm() < bubble.radius + support_;
    });
}

Vec3d SubgridAdvector::velocityAt(const Vec3d& x, double radius, const WaterVelocityField& water,
                                  const std::vector<BubbleState>& trapped, bool& inWater) const {
    const WaterVelocityField::Sample sample = water.sample(x, particleVolume_);
    inWater = sample.weight >= kInWater || besideTrappedBubble(x, trapped);
    return sample.velocity + riseSpeed(radius) * up_;
}

void SubgridAdvector::advance(std::vector<SubgridBubble>& bubbles, const WaterVelocityField& water,
                              const std::vector<BubbleState>& trapped, double seconds) const {
    const int steps = std::max(1, settings_.substeps);
    const double dt = seconds / steps;
    std::vector<bool> popped(bubbles.size(), false);
    for (std::size_t i = 0; i < bubbles.size(); ++i) {
        SubgridBubble& bubble = bubbles[i];
        for (int step = 0; step < steps && !popped[i]; ++step) {
            bool inWater = true;
            const Vec3d start = velocityAt(bubble.position, bubble.radius, water, trapped, inWater);
            if (!inWater) {
                popped[i] = true;
                break;
            }
            const Vec3d middle = bubble.position + 0.5 * dt * start;
            bubble.velocity = velocityAt(middle, bubble.radius, water, trapped, inWater);
            bubble.position += dt * bubble.velocity;
            bubble.age += dt;
        }
    }
    std::size_t kept = 0;
    for (std::size_t i = 0; i < bubbles.size(); ++i)
        if (!popped[i] && bubbles[i].age <= settings_.lifetime)
            bubbles[kept++] = bubbles[i];
    bubbles.resize(kept);
    removeSurfaced(bubbles, water, trapped);
}

void SubgridAdvector::removeSurfaced(std::vector<SubgridBubble>& bubbles,
                                     const WaterVelocityField& water,
                                     const std::vector<BubbleState>& trapped) const {
    std::erase_if(bubbles, [&](const SubgridBubble& bubble) {
        return water.sample(bubble.position, particleVolume_).weight < kInWater &&
               !besideTrappedBubble(bubble.position, trapped);
    });
}

} // namespace airtrap
