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
      fitter_(spacing, settings.minRadius * spacing), immersion_(spacing),
      upperProbes_(BubbleImmersion::hemisphere(Vec3d::UnitY())),
      minWetProbes_(int(std::ceil(settings.minWaterShare * BubbleImmersion::kProbeCount - 1e-9))) {}

std::size_t BubbleSpawner::spawn(const Bubbles& bubbles, std::uint64_t step, const Water& water,
                                 const std::vector<const RigidBody*>& solids, int frame,
                                 std::size_t limit) {
    if (limit == 0)
        return 0;
    const NeighborGrid& grid = water.grid;
    markSolidCells(grid, bubbles.alive, solids);
    const std::vector<AirPocket> pockets = finder_.find(grid, solid_);
    std::vector<FittedBubble> pool = candidates(pockets, water, solids);
    // The step count makes every search's choice its own, and the same on a resumed bake.
    SplitMix64 random(seed_ ^ (0xA1B2C3D4E5F60718ull * (step + 1)));
    std::size_t made = 0;
    while (!pool.empty() && made < limit) {
        const std::size_t pick = random.below(pool.size());
        const FittedBubble fitted = pool[pick];
        pool.erase(pool.begin() + static_cast<std::ptrdiff_t>(pick));
        BubbleState bubble;
        bubble.id = bubbles.nextId++;
        bubble.birthFrame = frame;
        bubble.radius = fitted.radius;
        bubble.body.position = fitted.centre;
        bubble.body.linearVelocity = surroundingVelocity(fitted, water);
        // Of the bubble as made: a body nearby may have shrunk it since the fit.
        bubble.areaFractionInWater =
            fitter_.areaFractionInWater(fitted.centre, fitted.radius, grid, water.positions);
        bubble.pocketVolume = fitted.pocketVolume;
        bubbles.alive.push_back(bubble);
        ++made;
    }
    return made;
}

namespace {

Vec3d cellCentre(const NeighborGrid& grid, int i, int j, int k) {
    return (grid.origin() +
            (Vec3f(float(i), float(j), float(k)) + Vec3f::Constant(0.5f)) * grid.cellSize())
        .cast<double>();
}

} // namespace

void BubbleSpawner::markSolidCells(const NeighborGrid& grid,
                                   const std::vector<BubbleState>& bubbles,
                                   const std::vector<const RigidBody*>& solids) {
    // A cell reaches into a solid when the solid comes nearer its centre than its corners are.
    const double halfDiagonal = 0.5 * std::sqrt(3.0) * grid.cellSize();
    const Vec3i& dims = grid.dimensions();
    if (staticSolid_.size() != grid.cellTotal()) {
        staticSolid_.assign(grid.cellTotal(), 0);
        for (int k = 0; k < dims.z(); ++k)
            for (int j = 0; j < dims.y(); ++j)
                for (int i = 0; i < dims.x(); ++i)
                    for (const RigidBody* body : solids)
                        if (!body->isMoving() &&
                            body->signedDistance(cellCentre(grid, i, j, k)) < halfDiagonal)
                            staticSolid_[grid.linearIndex(i, j, k)] = 1;
    }
    solid_ = staticSolid_;
    for (const RigidBody* body : solids)
        if (body->isMoving())
            markAround(grid, body->shapePose().position,
                       body->shape().boundingRadius() + halfDiagonal, solid_,
                       [&](const Vec3d& x) { return body->signedDistance(x) < halfDiagonal; });
    for (const BubbleState& bubble : bubbles) {
        const double reach = bubble.radius + halfDiagonal;
        markAround(grid, bubble.body.position, reach, solid_, [&](const Vec3d& x) {
            return (x - bubble.body.position).squaredNorm() < reach * reach;
        });
    }
}

template <class Inside>
void BubbleSpawner::markAround(const NeighborGrid& grid, const Vec3d& centre, double reach,
                               std::vector<std::uint8_t>& mask, Inside&& inside) const {
    const Vec3i low = grid.cellCoordinates((centre - Vec3d::Constant(reach)).cast<float>());
    const Vec3i high = grid.cellCoordinates((centre + Vec3d::Constant(reach)).cast<float>());
    for (int k = low.z(); k <= high.z(); ++k)
        for (int j = low.y(); j <= high.y(); ++j)
            for (int i = low.x(); i <= high.x(); ++i)
                if (inside(cellCentre(grid, i, j, k)))
                    mask[grid.linearIndex(i, j, k)] = 1;
}

std::vector<FittedBubble>
BubbleSpawner::candidates(const std::vector<AirPocket>& pockets, const Water& water,
                          const std::vector<const RigidBody*>& solids) const {
    std::vector<FittedBubble> fitted;
    for (const AirPocket& pocket : pockets) {
        std::optional<FittedBubble> bubble = fitter_.fit(pocket, water.grid, water.positions);
        if (!bubble)
            continue;
        // Like water, a body keeps half a spacing from the bubble's surface. A mesh body's field
        // reads at most its band's width (2.5 spacings), which caps bubbles inside its bounding
        // sphere at 2 spacings; those outside it are left alone.
        for (const RigidBody* body : solids) {
            const double clearance = (bubble->centre - body->shapePose().position).norm() -
                                     body->shape().boundingRadius();
            if (clearance > bubble->radius + 0.5 * spacing_)
                continue;
            bubble->radius =
                std::min(bubble->radius, body->signedDistance(bubble->centre) - 0.5 * spacing_);
        }
        if (bubble->radius >= settings_.minRadius * spacing_ && underWater(*bubble, water))
            fitted.push_back(*bubble);
    }
    return fitted;
}

bool BubbleSpawner::underWater(const FittedBubble& bubble, const Water& water) const {
    const BubbleImmersion::WetProbes wet =
        immersion_.measure(bubble.centre, bubble.radius, water.grid, water.positions);
    return coveredFromAbove(wet) && int(wet.count()) >= minWetProbes_;
}

bool BubbleSpawner::coveredFromAbove(const BubbleImmersion::WetProbes& wet) const {
    return int((wet & upperProbes_).count()) >= kLidProbes;
}

Vec3d BubbleSpawner::surroundingVelocity(const FittedBubble& bubble, const Water& water) const {
    const double reach = bubble.radius + water.grid.cellSize();
    Vec3d sum = Vec3d::Zero();
    std::size_t count = 0;
    water.grid.forEachRangeInBall(
        bubble.centre, reach, [&](std::uint32_t begin, std::uint32_t end) {
            for (std::uint32_t s = begin; s < end; ++s)
                if ((water.positions[s].cast<double>() - bubble.centre).norm() < reach) {
                    sum += water.particles.velocities[s].cast<double>();
                    ++count;
                }
        });
    return count > 0 ? Vec3d(sum / double(count)) : Vec3d::Zero();
}

} // namespace airtrap
