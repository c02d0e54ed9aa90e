#include "post/PostStage.h"

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "core/Parallel.h"
#include "post/FrameSolids.h"
#include "post/FreeSurface.h"
#include "post/WaterVolume.h"
#include "scene/SceneJson.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <optional>
#include <utility>

namespace airtrap {

namespace {

double secondsSince(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//! The sub-grid pass, for runs that make the sub-grid bubbles. Opening it adopts the settings
//! in subgrid.json, which part runs must leave to the one run after them.
std::optional<SubgridPass> subgridPassOf(const FrameCache& cache, const Scene& scene,
                                         const PostOptions& options) {
    if (!options.subgrid || !options.part.empty())
        return std::nullopt;
    return std::optional<SubgridPass>(std::in_place, cache, scene);
}

} // namespace

PostStage::PostStage(const FrameCache& cache, const Scene& scene, PostOptions options)
    : cache_(cache), scene_(scene), options_(std::move(options)), solids_(scene),
      store_(options_.part.empty()
                 ? PostStore::openOrEmpty(cache.directory(), storeDamage_)
                 : PostStore::openPart(cache.directory(), options_.part, storeDamage_)),
      subgrid_(subgridPassOf(cache, scene, options_)) {
    store_.useSettings(settingsOf(scene_));
}

nlohmann::json PostStage::settingsOf(const Scene& scene) {
    const nlohmann::json json = sceneToJson(scene);
    // The spacing sizes the voxels and the margin, so results made at another one are stale too.
    return {{"surface_mesh", json.at("surface_mesh")},
            {"particle_spacing", scene.solver.particleSpacing}};
}

void PostStage::makeFrame(int frame, Interrupter& interrupter, PostReport& report) {
    const auto start = std::chrono::steady_clock::now();
    const CacheManifest manifest = cache_.manifestSnapshot();
    const CacheFrameEntry* source = manifest.findFrame(frame);
    if (source == nullptr)
        throw Error(ErrorKind::InvalidInput,
                    "frame " + std::to_string(frame) + " is not in " + cache_.directory());
    if (store_.isCurrent(frame, source->crc32)) {
        const std::lock_guard lock(reportMutex_);
        ++report.alreadyCurrent;
        return;
    }
    std::string problem;
    const std::optional<FrameData> data = cache_.readIntactFrame(frame, problem);
    if (!data) {
        const std::lock_guard lock(reportMutex_);
        report.damaged.push_back(problem);
        return;
    }
    const double spacing = scene_.solver.particleSpacing;
    Interrupter part(&interrupter);
    const WaterVolume water =
        WaterVolume::build(data->state.fluid, spacing, scene_.surfaceMesh, scene_.domain(), &part);
    if (part.stopRequested())
        return;
    const TriangleMesh surface = renderedSurface(water.mesh(), FrameSolids(solids_, data->state),
                                                 scene_.surfaceMesh, spacing);
    PostFrameEntry entry{frame, source->crc32, surface.triangleCount(), secondsSince(start)};
    store_.writeFrame(entry, surface, water);
    const std::lock_guard lock(reportMutex_);
    ++report.made;
    report.secondsPerFrame += entry.seconds;
}

void PostStage::addSubgridBubbles(int lastFrame, Interrupter& interrupter, PostReport& report) {
    report.subgrid = subgrid_->run(lastFrame, interrupter);
    const std::string& damaged = report.subgrid.damaged;
    // The surface pass has reported it already when the frame was one of its own.
    if (!damaged.empty() &&
        std::find(report.damaged.begin(), report.damaged.end(), damaged) == report.damaged.end())
        report.damaged.push_back(damaged);
}

void PostStage::prepareStore(PostReport& report) {
    // Part runs work beside each other, perhaps on other machines, where a temporary of a
    // process that is not running here may be another machine's write under way.
    if (!options_.part.empty())
        return;
    // A post killed mid-write left its temporaries (the sub-grid files share the folder); this
    // run makes those results again.
    AtomicFile::removeOrphanedTemporaries(store_.directory());
    report.mergedFrames = store_.mergeParts(report.replacedLists);
}

PostReport PostStage::run(const std::vector<int>& frames, Interrupter& interrupter) {
    const auto start = std::chrono::steady_clock::now();
    PostReport report;
    if (!storeDamage_.empty())
        report.replacedLists.push_back(storeDamage_);
    if (subgrid_ && !subgrid_->storeDamage().empty())
        report.replacedLists.push_back(subgrid_->storeDamage());
    prepareStore(report);
    interrupter.start("post");
    std::atomic<int> done{0};
    std::mutex progressMutex;
    // A frame that fails (a full disk) stops the frames not yet begun; those under way finish.
    // Its error must not leave the loop's body: TBB would cancel the loop's task group, and with
    // it the OpenVDB work of the frames under way, halfway through building their trees.
    Interrupter frameStop(&interrupter);
    std::exception_ptr firstFailure;
    parallelFor(std::size_t(0), frames.size(), [&](std::size_t i) {
        if (frameStop.stopRequested())
            return;
        try {
            makeFrame(frames[i], frameStop, report);
        } catch (...) {
            const std::lock_guard lock(progressMutex);
            if (!firstFailure)
                firstFailure = std::current_exception();
            frameStop.requestStop();
            return;
        }
        const int finished = ++done;
        const std::lock_guard lock(progressMutex);
        interrupter.wasInterrupted(100.0 * finished / double(frames.size()));
    });
    interrupter.end();
    if (firstFailure)
        std::rethrow_exception(firstFailure);
    if (subgrid_ && !frames.empty() && !interrupter.stopRequested())
        addSubgridBubbles(*std::max_element(frames.begin(), frames.end()), interrupter, report);
    report.stopped =
        (interrupter.stopRequested() && done < int(frames.size())) || report.subgrid.stopped;
    report.seconds = secondsSince(start);
    if (report.made > 0)
        report.secondsPerFrame /= report.made;
    return report;
}

} // namespace airtrap
