#include "bubbles/BubbleSpawner.h"

#include <algorithm>
#include <cmath>

namespace airtrap {
namespace {

//! SplitMix64 (Steele, Lea & Flood 2014): a tiny generator whose stream is the same on every
//! platform and library, unlike std::uniform_int_distribution's.
class SplitMix64 {
public:
    explicit SplitMix64(std::uint64_t seed) : state_(seed) {}
    std::uint64_t next() {
        std::uint64_t z = (state_ += 0x9E3779B97F4A7C15ull);
        z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
        z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
        return z ^ (z >> 31);
    }
    //! Uniform in [0, n) (the modulo bias is below 2⁻⁵⁰ for any pocket count).
    std::size_t below(std::size_t n) { return static_cast<std::size_t>(next() % n); }

private:
    std::uint64_t state_;
};

} // namespace

BubbleSpawner::BubbleSpawner(const BubbleSettings& settings, double spacing, std::uint64_t seed)
    : settings_(settings), spacing_(spacing), seed_(seed),
      fitter_(spacing, settings.minRadius * spacing) {}

std::size_t BubbleSpawner::spawn(SimulationState& state, const Water& water,
                                 const std::vector<const RigidBody*>& solids, int frame) {
    if (settings_.maxNewPerFrame <= 0)
        return 0;
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * water.grid.cellSize();
    const std::vector<AirPocket> pockets =
        finder_.find(water.grid, [&](const Vec3d& centre) {
            return cellIsSolid(centre, halfDiagonal, state, solids);
        });
    std::vector<FittedBubble> pool = candidates(pockets, water, solids);
    SplitMix64 random(seed_ ^ (0xA1B2C3D4E5F60718ull * static_cast<std::uint64_t>(frame)));
    std::size_t made = 0;
    while (!pool.empty() && made < static_cast<std::size_t>(settings_.maxNewPerFrame)) {
        const std::size_t pick = random.below(pool.size());
        const FittedBubble fitted = pool[pick];
        pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(pick));
        BubbleState bubble;
        bubble.id = state.nextBubbleId++;
        bubble.birthFrame = frame;
        bubble.radius = fitted.radius;
        bubble.body.position = fitted.centre;
        bubble.body.linearVelocity = surroundingVelocity(fitted, water);
        bubble.areaFractionInWater = fitted.areaFractionInWater;
        bubble.pocketVolume = fitted.pocketVolume;
        state.bubbles.push_back(bubble);
        ++made;
    }
    return made;
}

bool BubbleSpawner::cellIsSolid(const Vec3d& centre, double halfDiagonal,
                                const SimulationState& state,
                                const std::vector<const RigidBody*>& solids) const {
    for (const BubbleState& bubble : state.bubbles)
        if ((centre - bubble.body.position).norm() < bubble.radius + halfDiagonal)
            return true;
    for (const RigidBody* body : solids)
        if (body->signedDistance(centre) < halfDiagonal)
            return true;
    return false;
}

std::vector<FittedBubble> BubbleSpawner::candidates(const std::vector<AirPocket>& pockets,
                                                    const Water& water,
                                                    const std::vector<const RigidBody*>& solids)
    const {
    std::vector<FittedBubble> fitted;
    for (const AirPocket& pocket : pockets) {
        std::optional<FittedBubble> bubble = fitter_.fit(pocket, water.grid, water.positions);
        if (!bubble)
            continue;
        // Like water, a body keeps half a spacing from the bubble's surface.
        for (const RigidBody* body : solids)
            bubble->radius =
                std::min(bubble->radius, body->signedDistance(bubble->centre) - 0.5 * spacing_);
        if (bubble->radius >= settings_.minRadius * spacing_)
            fitted.push_back(*bubble);
    }
    return fitted;
}

Vec3d BubbleSpawner::surroundingVelocity(const FittedBubble& bubble, const Water& water) const {
    const NeighborGrid& grid = water.grid;
    const double reach = bubble.radius + grid.cellSize();
    const Vec3i low = grid.cellCoordinates((bubble.centre - Vec3d::Constant(reach)).cast<float>());
    const Vec3i high = grid.cellCoordinates((bubble.centre + Vec3d::Constant(reach)).cast<float>());
    Vec3d sum = Vec3d::Zero();
    std::size_t count = 0;
    for (int k = low.z(); k <= high.z(); ++k)
        for (int j = low.y(); j <= high.y(); ++j) {
            const std::uint32_t begin = grid.cellRange(grid.linearIndex(low.x(), j, k)).first;
            const std::uint32_t end = grid.cellRange(grid.linearIndex(high.x(), j, k)).second;
            for (std::uint32_t s = begin; s < end; ++s)
                if ((water.positions[s].cast<double>() - bubble.centre).norm() < reach) {
                    sum += water.particles.velocities[s].cast<double>();
                    ++count;
                }
        }
    return count > 0 ? Vec3d(sum / double(count)) : Vec3d::Zero();
}

} // namespace airtrap
