#include "post/SubgridSpawner.h"

#include "core/Error.h"
#include "post/Icosphere.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>
#include <string>

namespace airtrap {

namespace {

void check(bool ok, const std::string& what) {
    if (!ok)
        throw Error(ErrorKind::InvalidInput, "sub-grid bubbles: " + what);
}

} // namespace

SubgridSpawner::SubgridSpawner(const SubgridBubbleSettings& settings, std::uint64_t seed)
    : settings_(settings), seed_(seed), directions_(unitIcosphere(1).vertices) {
    constexpr int kSites = 3 * kSitesPerShell;
    // The sites index the once-subdivided icosahedron's vertices, 42 of them.
    check(directions_.size() == std::size_t(kSitesPerShell), "icosphere has the wrong size");
    check(settings.maxPerBubble >= 0 && settings.maxPerBubble <= kSites,
          "max per bubble " + std::to_string(settings.maxPerBubble) + ", expected 0 to " +
              std::to_string(kSites));
    check(settings.minSize > 0.0 && settings.minSize <= settings.maxSize && settings.maxSize <= 0.5,
          "sizes " + std::to_string(settings.minSize) + " to " + std::to_string(settings.maxSize) +
              ", expected 0 < min ≤ max ≤ 0.5 of the parent's radius");
    check(settings.generations >= 1 && settings.generations <= 4,
          "generations " + std::to_string(settings.generations) + ", expected 1 to 4");
    check(settings.childrenPerBubble >= 0 && settings.childrenPerBubble <= kSites,
          "children per bubble " + std::to_string(settings.childrenPerBubble) + ", expected 0 to " +
              std::to_string(kSites));
}

int SubgridSpawner::countFor(double areaFractionInWater) const {
    const double gap = 1.0 - std::clamp(areaFractionInWater, 0.0, 1.0);
    return int(std::lround(settings_.maxPerBubble * gap));
}

std::vector<SubgridBubble> SubgridSpawner::shed(const BubbleState& parent,
                                                std::uint32_t& nextId) const {
    // One stream per trapped bubble: the same bubble sheds the same sub-grid bubbles in any run.
    std::seed_seq seeds{std::uint32_t(seed_), std::uint32_t(seed_ >> 32), parent.id};
    std::mt19937_64 random(seeds);
    SubgridBubble root;
    root.id = parent.id;
    root.generation = 0;
    root.position = parent.body.position;
    root.radius = parent.radius;
    root.velocity = parent.body.linearVelocity;
    std::vector<SubgridBubble> out;
    shedAround(root, countFor(parent.areaFractionInWater), random, nextId, out);
    // Later generations shed from the earlier ones, breadth first, so ids follow generations.
    for (std::size_t i = 0; i < out.size(); ++i)
        if (out[i].generation < settings_.generations) {
            const SubgridBubble source = out[i]; // `out` grows: no reference into it
            shedAround(source, settings_.childrenPerBubble, random, nextId, out);
        }
    return out;
}

void SubgridSpawner::shedAround(const SubgridBubble& parent, int count, std::mt19937_64& random,
                                std::uint32_t& nextId, std::vector<SubgridBubble>& out) const {
    std::array<int, 3 * kSitesPerShell> sites;
    std::iota(sites.begin(), sites.end(), 0);
    // A partial Fisher–Yates shuffle: `count` distinct sites, each equally likely.
    std::uniform_real_distribution<double> size(settings_.minSize, settings_.maxSize);
    for (int k = 0; k < count; ++k) {
        std::uniform_int_distribution<int> pick(k, int(sites.size()) - 1);
        std::swap(sites[std::size_t(k)], sites[std::size_t(pick(random))]);
        const int site = sites[std::size_t(k)];
        const double shell = kShellRadii[site / kSitesPerShell];
        const Vec3d& direction = directions_[std::size_t(site % kSitesPerShell)];
        SubgridBubble bubble;
        bubble.id = nextId++;
        bubble.parentId = parent.id;
        bubble.generation = parent.generation + 1;
        bubble.position = parent.position + shell * parent.radius * direction;
        bubble.radius = size(random) * parent.radius;
        bubble.velocity = parent.velocity;
        out.push_back(bubble);
    }
}

} // namespace airtrap
