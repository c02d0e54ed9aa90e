#include "bake/Baker.h"

#include "cache/FrameCache.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "scene/SceneJson.h"
#include "sim/BodyBuilder.h"
#include "sim/Simulation.h"

#include <algorithm>
#include <chrono>
#include <memory>

namespace airtrap {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

//! Returns the simulation positioned at the last frame before the cache's first damaged one (or
//! at `firstFrame − 1` when that is asked for), or null when there is nothing to continue from.
//! Every frame after a damaged one is baked again: each is the continuation of the one before.
std::unique_ptr<Simulation> resumeFrom(FrameCache& cache, const Scene& scene, int firstFrame,
                                       const std::function<void(const std::string&)>& say) {
    std::vector<std::string> problems;
    int from = cache.lastFrameBeforeDamage(&problems);
    const std::vector<int> listed = cache.frames();
    for (const std::string& problem : problems)
        say("damaged frame: " + problem + "; it and the " +
            std::to_string(std::max<std::ptrdiff_t>(
                0, std::ptrdiff_t(listed.end() -
                                  std::upper_bound(listed.begin(), listed.end(), from + 1)))) +
            " frame(s) after it are baked again");
    if (firstFrame > 0) {
        if (firstFrame - 1 > from)
            throw Error(ErrorKind::InvalidInput, cache.directory() + ": cannot start at frame " +
                                                     std::to_string(firstFrame) + ": frame " +
                                                     std::to_string(firstFrame - 1) +
                                                     " is not in the cache (last good "
                                                     "frame: " +
                                                     std::to_string(from) + ")");
        from = firstFrame - 1;
    }
    cache.truncateAfter(from);
    if (from == 0)
        return nullptr;
    FrameData data = cache.readFrame(from);
    say("continuing from frame " + std::to_string(from) +
        " (t = " + std::to_string(data.state.time) + " s)");
    return std::make_unique<Simulation>(scene, std::move(data.state));
}

} // namespace

Baker::Baker(Scene scene, BakeOptions options)
    : scene_(std::move(scene)), options_(std::move(options)) {}

void Baker::report(const std::string& message) const {
    if (onMessage_)
        onMessage_(message);
}

FrameCache Baker::openCache() const {
    const std::string hash = parameterHash(scene_);
    const bool continuing = options_.resume || options_.firstFrame > 1;
    FrameCache cache = continuing && FrameCache::isCache(options_.cacheDir) ? openOrRebuild(hash)
                       : continuing && FrameCache::holdsFrameFiles(options_.cacheDir)
                           ? rebuiltCache(hash, "was missing")
                           : FrameCache::create(options_.cacheDir, cachedSceneJson(), hash,
                                                scene_.frames.fps, options_.overwrite);
    if (continuing)
        repairRecordedScene(cache, hash);
    if (cache.manifest().parameterHash != hash && continuing && options_.adoptEditedScene)
        adoptEditedScene(cache);
    if (cache.manifest().parameterHash != hash)
        throw Error(ErrorKind::InvalidInput,
                    options_.cacheDir + " was baked from a different scene (parameter hash " +
                        cache.manifest().parameterHash + ", this scene " + hash +
                        "); bake into another folder or start again with --overwrite");
    // A bake killed mid-write left its temporary; this bake writes that frame again.
    AtomicFile::removeOrphanedTemporaries(options_.cacheDir);
    return cache;
}

void Baker::repairRecordedScene(FrameCache& cache, const std::string& hash) const {
    const std::string damage = cache.recordedSceneDamage();
    if (damage.empty())
        return;
    // The scene and its hash disagree, so one of them is damaged. When either is this scene's,
    // the frames are this scene's and both are written again; otherwise the check below refuses
    // the cache as another scene's.
    std::string recordedHash;
    try {
        recordedHash = parameterHash(sceneFromJson(cache.manifest().scene, ""));
    } catch (const Error&) {
    }
    if (cache.manifest().parameterHash != hash && recordedHash != hash)
        return;
    cache.replaceScene(cachedSceneJson(), hash);
    report(damage + ": damaged; written again from this scene");
}

FrameCache Baker::openOrRebuild(const std::string& hash) const {
    try {
        return FrameCache::open(options_.cacheDir);
    } catch (const Error& error) {
        // A manifest of a newer Airtrap is not damaged: this build must not replace it.
        if (error.kind() != ErrorKind::CacheCorrupt ||
            CacheManifest::isFromANewerBuild(options_.cacheDir + "/" + CacheManifest::kFileName))
            throw;
        return rebuiltCache(hash, "was damaged (" + std::string(error.what()) + ")");
    }
}

FrameCache Baker::rebuiltCache(const std::string& hash, const std::string& why) const {
    // The frames are taken as this scene's: a frame file holds no trace of the scene it was
    // baked from beyond its time, which rebuild() checks against this scene's frame rate.
    std::vector<std::string> notes;
    FrameCache cache = FrameCache::rebuild(options_.cacheDir, cachedSceneJson(), hash,
                                           scene_.frames.fps, why, notes);
    for (const std::string& note : notes)
        report(note);
    return cache;
}

void Baker::adoptEditedScene(FrameCache& cache) const {
    // Particle mass and the kernel follow from these; cached particles made with other values
    // would be out of balance with the new ones from the first step.
    static const char* const kFixedForParticles[] = {"particle_spacing", "support_factor",
                                                     "rest_density"};
    const nlohmann::json& cachedSolver = cache.manifest().scene["solver"];
    const nlohmann::json solver = sceneToJson(scene_)["solver"];
    for (const char* key : kFixedForParticles)
        if (cachedSolver.value(key, nlohmann::json()) != solver[key])
            throw Error(ErrorKind::InvalidInput,
                        options_.cacheDir + ": solver." + key + " changed from " +
                            cachedSolver.value(key, nlohmann::json()).dump() + " to " +
                            solver[key].dump() +
                            "; the cached particles were made with the old value, so the bake "
                            "must start again from frame 1");
    const std::size_t cachedBodies =
        cache.manifest().scene.value("bodies", nlohmann::json::array()).size();
    if (cachedBodies != scene_.bodies.size())
        throw Error(ErrorKind::InvalidInput,
                    options_.cacheDir + ": the scene now has " +
                        std::to_string(scene_.bodies.size()) + " bodies, the cached frames " +
                        std::to_string(cachedBodies) +
                        "; the frames hold no state for a new body, so the bake must start again "
                        "from frame 1");
    cache.replaceScene(cachedSceneJson(), parameterHash(scene_));
}

nlohmann::json Baker::cachedSceneJson() const {
    // The copy lives in the cache folder, not beside the scene file: mesh paths relative to the
    // scene would point nowhere from there.
    return sceneToJson(BodyBuilder::withAbsoluteMeshPaths(scene_));
}

std::unique_ptr<Simulation> Baker::startingPoint(FrameCache& cache) {
    const bool continuing = options_.resume || options_.firstFrame > 1;
    std::unique_ptr<Simulation> simulation;
    if (continuing)
        simulation = resumeFrom(cache, scene_, options_.firstFrame,
                                [this](const std::string& m) { report(m); });
    if (!simulation) {
        simulation = std::make_unique<Simulation>(scene_);
        cache.writeFrame(simulation->state(), simulation->lastFrameStats());
        if (onFrame_)
            onFrame_(1, simulation->lastFrameStats());
    }
    return simulation;
}

Simulation::Advance Baker::bakeFrame(Simulation& simulation, FrameCache& cache,
                                     Interrupter& interrupter, BakeProgress progress) {
    const auto frameStart = Clock::now();
    const std::uint64_t stepsAtStart = simulation.state().steps;
    progress.frame = simulation.frame() + 1;
    const auto onStep = [&](double frameFraction) {
        const double elapsed = secondsSince(frameStart);
        progress.frameFraction = frameFraction;
        progress.simTime = simulation.state().time;
        progress.particles = simulation.state().fluid.size();
        progress.bubbles = simulation.state().bubbles.size();
        progress.stepsPerSecond =
            elapsed > 0.0 ? double(simulation.state().steps - stepsAtStart) / elapsed : 0.0;
        if (onProgress_)
            onProgress_(progress);
    };
    const Simulation::Advance advance = simulation.advanceFrame(interrupter, onStep);
    for (const std::string& notice : simulation.takeNotices())
        report(notice);
    if (advance == Simulation::Advance::FrameDone) {
        cache.writeFrame(simulation.state(), simulation.lastFrameStats());
        if (onFrame_)
            onFrame_(simulation.frame(), simulation.lastFrameStats());
    }
    return advance;
}

Baker::Outcome Baker::run(Interrupter& interrupter) {
    const int lastFrame = options_.lastFrame > 0 ? options_.lastFrame : scene_.frames.endFrame;
    std::unique_ptr<Simulation> simulation;
    FrameCache cache = openCache();
    try {
        simulation = startingPoint(cache);
        cache.setStatus("baking");
        const Outcome outcome = bakeFrames(*simulation, cache, interrupter, lastFrame);
        if (outcome == Outcome::Stopped)
            cache.setStatus("stopped");
        else
            cache.setStatus(lastFrame == scene_.frames.endFrame
                                ? "complete"
                                : "baked to frame " + std::to_string(lastFrame));
        return outcome;
    } catch (const Error& error) {
        recordFailure(cache, error);
        throw;
    }
}

Baker::Outcome Baker::bakeFrames(Simulation& simulation, FrameCache& cache,
                                 Interrupter& interrupter, int lastFrame) {
    const int startFrame = simulation.frame();
    const auto bakeStart = Clock::now();
    while (simulation.frame() < lastFrame) {
        // A stop that arrived during a frame's last step lets that frame finish and land.
        if (interrupter.stopRequested())
            return Outcome::Stopped;
        BakeProgress progress;
        progress.lastFrame = lastFrame;
        const int framesDone = simulation.frame() - startFrame;
        if (framesDone > 0)
            progress.etaSeconds =
                secondsSince(bakeStart) / framesDone * (lastFrame - simulation.frame());
        if (bakeFrame(simulation, cache, interrupter, progress) == Simulation::Advance::Interrupted)
            return Outcome::Stopped;
    }
    return Outcome::Completed;
}

void Baker::recordFailure(FrameCache& cache, const Error& error) const {
    // The disk that failed the bake may fail this write too; the original error is what the
    // user needs to see, so this one is dropped.
    try {
        cache.setStatus(std::string("failed: ") + error.what());
    } catch (const Error&) {
    }
}

} // namespace airtrap
