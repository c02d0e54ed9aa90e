#include "post/SubgridPass.h"

#include "core/Error.h"
#include "post/WaterVelocityField.h"
#include "scene/SceneJson.h"

#include <algorithm>
#include <chrono>
#include <optional>

namespace airtrap {

SubgridPass::SubgridPass(const FrameCache& cache, const Scene& scene)
    : cache_(cache), scene_(scene), spawner_(scene.subgridBubbles, scene.seed),
      advector_(scene.subgridBubbles, scene),
      store_(SubgridStore::openOrEmpty(cache.directory(), storeDamage_)) {
    store_.useSettings(settingsOf(scene_));
}

nlohmann::json SubgridPass::settingsOf(const Scene& scene) {
    const nlohmann::json json = sceneToJson(scene);
    const nlohmann::json& bubbles = json.at("bubbles");
    return {{"subgrid_bubbles", json.at("subgrid_bubbles")},
            {"seed", scene.seed},
            {"kinematic_viscosity", bubbles.at("kinematic_viscosity")},
            {"max_rise_speed", bubbles.at("max_rise_speed")},
            {"solver", json.at("solver")},
            {"fps", scene.frames.fps}};
}

SubgridFrame SubgridPass::step(const SubgridFrame& previous, const SimulationState& state,
                               double seconds) const {
    SubgridFrame next{state.nextBubbleId, previous.nextId, previous.bubbles};
    std::vector<SubgridBubble> born;
    for (const BubbleState& bubble : state.bubbles) {
        if (bubble.id < previous.trappedIdsBelow)
            continue;
        const std::vector<SubgridBubble> shed = spawner_.shed(bubble, next.nextId);
        born.insert(born.end(), shed.begin(), shed.end());
    }
    if (next.bubbles.empty() && born.empty())
        return next; // nothing to carry: spare binning the water
    const WaterVelocityField water(state.fluid, scene_.supportRadius());
    if (seconds > 0.0)
        advector_.advance(next.bubbles, water, state.bubbles, seconds);
    // The shells may reach past the water's surface; bubbles placed there have already popped.
    advector_.removeSurfaced(born, water, state.bubbles);
    next.bubbles.insert(next.bubbles.end(), born.begin(), born.end());
    return next;
}

SubgridReport SubgridPass::run(int lastFrame, Interrupter& interrupter) {
    const auto start = std::chrono::steady_clock::now();
    interrupter.start("sub-grid bubbles");
    SubgridReport report;
    try {
        report = walk(lastFrame, true, interrupter);
    } catch (const Error& error) {
        if (error.kind() != ErrorKind::CacheCorrupt)
            throw;
        // A stored frame the next one starts from is damaged: make them all again.
        report = walk(lastFrame, false, interrupter);
    }
    interrupter.end();
    report.seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return report;
}

bool SubgridPass::makeFrame(const CacheFrameEntry& entry, std::uint32_t chain, int previousFrame,
                            std::optional<SubgridFrame>& previous, SubgridReport& report) {
    if (!previous)
        previous = store_.readFrame(previousFrame);
    const std::optional<FrameData> data = cache_.readIntactFrame(entry.frame, report.damaged);
    if (!data)
        return false;
    const double seconds =
        previousFrame == 0 ? 0.0 : scene_.frameTime(entry.frame) - scene_.frameTime(previousFrame);
    previous = step(*previous, data->state, seconds);
    store_.writeFrame({entry.frame, chain, std::uint32_t(previous->bubbles.size())}, *previous);
    ++report.made;
    return true;
}

SubgridReport SubgridPass::walk(int lastFrame, bool trustStore, Interrupter& interrupter) {
    SubgridReport report;
    const CacheManifest manifest = cache_.manifestSnapshot();
    const auto upToLast =
        std::count_if(manifest.frames.begin(), manifest.frames.end(),
                      [&](const CacheFrameEntry& entry) { return entry.frame <= lastFrame; });
    std::uint32_t chain = 0;
    std::optional<SubgridFrame> previous = SubgridFrame{}; // before the first frame: none
    int previousFrame = 0;
    for (std::size_t i = 0; i < std::size_t(upToLast); ++i) {
        const CacheFrameEntry& entry = manifest.frames[i];
        if (interrupter.stopRequested()) {
            report.stopped = true;
            break;
        }
        chain = SubgridStore::chainCrc32(chain, entry.crc32);
        if (trustStore && store_.isCurrent(entry.frame, chain)) {
            ++report.alreadyCurrent;
            previous.reset(); // read only if the next frame needs it
        } else if (!makeFrame(entry, chain, previousFrame, previous, report)) {
            break; // damaged: the frames after it start from it
        }
        previousFrame = report.lastFrame = entry.frame;
        interrupter.wasInterrupted(100.0 * double(i + 1) / double(upToLast));
    }
    if (const SubgridFrameEntry* last = store_.entry(report.lastFrame))
        report.lastFrameBubbles = last->bubbles;
    return report;
}

} // namespace airtrap
