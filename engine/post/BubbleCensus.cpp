#include "post/BubbleCensus.h"

#include <algorithm>

namespace airtrap {
namespace {

//! The water of a frame, sorted by the cells of a grid over the scene's domain, so the probes
//! read only the particles near them.
struct SortedWater {
    NeighborGrid grid;
    PositionArrays positions;

    SortedWater(const Scene& scene, const std::vector<Vec3f>& particles)
        : grid(scene.domain(), float(scene.supportRadius())) {
        grid.build(particles);
        positions.gather(particles, grid.order());
    }
};

Vec3d upOf(const Scene& scene) {
    const Vec3d g = scene.solver.gravity;
    return g.squaredNorm() > 0.0 ? Vec3d(-g.normalized()) : Vec3d::UnitY();
}

} // namespace

BubbleCensus::BubbleCensus(const Scene& scene)
    : scene_(scene), immersion_(scene.solver.particleSpacing) {}

double BubbleCensus::slipSpeed(const BubbleState& bubble, const Vec3d& up) {
    // The water's velocity as the bake last measured it around the bubble (every 0.25 ms of
    // simulated time), the one eq. 5 steers the rise against.
    const Vec3d water =
        bubble.surroundings.measured ? bubble.surroundings.waterVelocity : Vec3d::Zero();
    return (bubble.body.linearVelocity - water).dot(up);
}

double BubbleCensus::targetRiseSpeed(double radius) const {
    const double stokes = 2.0 / 9.0 * scene_.solver.gravity.norm() * radius * radius /
                          scene_.bubbles.kinematicViscosity;
    return std::min(stokes, scene_.bubbles.maxRiseSpeed);
}

double BubbleCensus::waterDepthOver(const Vec3d& centre, double radius, const NeighborGrid& grid,
                                    const PositionArrays& positions) const {
    const double spacing = scene_.solver.particleSpacing;
    const Vec3d up = upOf(scene_);
    const Aabb domain = scene_.domain();
    double height = radius + 0.5 * spacing;
    double depth = 0.0;
    for (;;) {
        const Vec3d probe = centre + height * up;
        if (!grid.contains(probe.cast<float>()))
            return depth;
        bool wet = false;
        grid.forEachRangeInBall(probe, spacing, [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t s = begin; s < end && !wet; ++s)
                wet = (positions[s].cast<double>() - probe).squaredNorm() < spacing * spacing;
        });
        if (!wet)
            return depth;
        depth = height;
        height += spacing;
        if (height > domain.size().norm())
            return depth;
    }
}

BubbleCensusFrame BubbleCensus::add(const FrameData& data) {
    const SimulationState& state = data.state;
    BubbleCensusFrame row;
    row.frame = state.frame;
    row.time = state.time;
    row.alive = int(state.bubbles.size());
    row.created = int(data.stats.bubbles.created);
    row.deleted = data.stats.bubbles.deletedTotal();
    row.booksBalance = std::uint64_t(state.nextBubbleId) ==
                       state.bubbles.size() + state.bubblesDeleted.deletedTotal();

    const SortedWater water(scene_, state.fluid.positions);
    const Vec3d up = upOf(scene_);
    std::map<std::uint32_t, double> ages;
    double riseSum = 0.0, slipSum = 0.0, targetSum = 0.0;
    for (const BubbleState& bubble : state.bubbles) {
        const Vec3d& centre = bubble.body.position;
        const auto placement = BubbleImmersion::placement(
            immersion_.measure(centre, bubble.radius, water.grid, water.positions));
        if (placement == BubbleImmersion::Placement::InWater) {
            ++row.inWater;
            riseSum += bubble.body.linearVelocity.dot(up);
            slipSum += slipSpeed(bubble, up);
            targetSum += targetRiseSpeed(bubble.radius);
        } else if (placement == BubbleImmersion::Placement::Floating) {
            ++row.floating;
        } else {
            ++row.airborne;
        }
        if (!lastAge_.count(bubble.id)) {
            ++totals_.newBubblesMeasured;
            ++(placement == BubbleImmersion::Placement::InWater    ? totals_.newInWater
               : placement == BubbleImmersion::Placement::Floating ? totals_.newFloating
                                                                   : totals_.newAirborne);
            depthSum_ += waterDepthOver(centre, bubble.radius, water.grid, water.positions);
        }
        ages[bubble.id] = bubble.age;
    }
    for (const auto& [id, age] : lastAge_)
        if (!ages.count(id)) {
            ++totals_.ended;
            lifetimeSum_ += age;
        }
    lastAge_ = std::move(ages);
    if (row.inWater > 0) {
        row.meanRiseSpeedInWater = riseSum / row.inWater;
        row.meanSlipSpeedInWater = slipSum / row.inWater;
        row.meanTargetRiseSpeed = targetSum / row.inWater;
    }

    ++totals_.frames;
    totals_.bubbleFrames += std::uint64_t(row.alive);
    totals_.inWater += std::uint64_t(row.inWater);
    totals_.floating += std::uint64_t(row.floating);
    totals_.airborne += std::uint64_t(row.airborne);
    riseSum_ += riseSum;
    slipSum_ += slipSum;
    targetSum_ += targetSum;
    if (totals_.inWater > 0) {
        totals_.meanRiseSpeedInWater = riseSum_ / double(totals_.inWater);
        totals_.meanSlipSpeedInWater = slipSum_ / double(totals_.inWater);
        totals_.meanTargetRiseSpeed = targetSum_ / double(totals_.inWater);
    }
    totals_.created = state.nextBubbleId;
    totals_.alive = state.bubbles.size();
    totals_.deleted = state.bubblesDeleted;
    totals_.booksBalance = totals_.booksBalance && row.booksBalance;
    if (totals_.newBubblesMeasured > 0)
        totals_.meanDepthAtCreation = depthSum_ / double(totals_.newBubblesMeasured);
    if (totals_.ended > 0)
        totals_.meanLifetime = lifetimeSum_ / double(totals_.ended);
    frames_.push_back(row);
    return row;
}

double BubbleCensus::meanInWaterFrom(int firstFrame) const {
    double sum = 0.0;
    int count = 0;
    for (const BubbleCensusFrame& row : frames_)
        if (row.frame >= firstFrame) {
            sum += row.inWater;
            ++count;
        }
    return count == 0 ? 0.0 : sum / count;
}

} // namespace airtrap
