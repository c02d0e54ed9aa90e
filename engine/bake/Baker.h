#pragma once
// The bake loop both the CLI and the editor run: Scene → Simulation → FrameCache, one frame at a
// time, every finished frame written atomically before the next one starts, so a stop, a crash or
// a blow-up never loses a finished frame and `resume` continues bit-for-bit.
#include "bake/BakeProgress.h"
#include "core/Interrupter.h"
#include "scene/Scene.h"
#include "sim/FrameStats.h"
#include "sim/Simulation.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

class Error;
class FrameCache;

struct BakeOptions {
    std::string cacheDir;
    //! Continue from the last good frame of an existing cache of the same scene.
    bool resume = false;
    //! Replace an existing cache (only its own files are removed).
    bool overwrite = false;
    //! First frame to compute; frame first − 1 must be cached (0 = 2 on a new bake, the frame
    //! after the last good one when resuming). Frame 1 is the initial state, always written.
    int firstFrame = 0;
    //! Last frame to compute (0 = the scene's end frame).
    int lastFrame = 0;
    //! When continuing, accept a cache baked from an edited version of the scene: the kept frames
    //! stay and the bake goes on with the new settings (the editor's "change from here"). Settings
    //! that fix the particles themselves (spacing, support, rest density) must not differ.
    bool adoptEditedScene = false;
};

class Baker {
public:
    using ProgressCallback = std::function<void(const BakeProgress&)>;
    using FrameCallback = std::function<void(int frame, const FrameStats&)>;
    using MessageCallback = std::function<void(const std::string&)>;

    enum class Outcome { Completed, Stopped };

    //! The scene must have passed validation.
    Baker(Scene scene, BakeOptions options);

    void onProgress(ProgressCallback callback) { onProgress_ = std::move(callback); }
    //! Called after each frame is safely on disk.
    void onFrame(FrameCallback callback) { onFrame_ = std::move(callback); }
    //! Notes for the user (skipped corrupt frames, where the bake resumes).
    void onMessage(MessageCallback callback) { onMessage_ = std::move(callback); }

    //! Runs until the last frame or until the interrupter asks to stop (then after the current
    //! step, keeping every finished frame). Throws airtrap::Error for bad caches, I/O failures
    //! and blow-ups; the manifest's status records why the bake ended ("complete", "baked to
    //! frame N" when stopped short of the scene's end on purpose, "stopped", "failed: …").
    Outcome run(Interrupter& interrupter);

private:
    void report(const std::string& message) const;
    //! Creates the cache, or opens it to continue, and checks it belongs to this scene.
    FrameCache openCache() const;
    //! Lets a continued bake go on under the edited scene, or explains why it cannot.
    //! The scene as the cache's manifest keeps it.
    nlohmann::json cachedSceneJson() const;
    void adoptEditedScene(FrameCache& cache) const;
    //! The cache in cacheDir, its lost manifest rebuilt from the frame files (a resume).
    //! Writes the manifest's record of the scene again when it is damaged and the frames are
    //! this scene's (recordedSceneDamage()).
    void repairRecordedScene(FrameCache& cache, const std::string& hash) const;
    //! The cache to continue; a damaged manifest (not one of a newer Airtrap) is rebuilt from
    //! the frame files, as a lost one is.
    FrameCache openOrRebuild(const std::string& hash) const;
    //! The cache listed again from its frame files; `why` ("was missing") goes to the messages.
    FrameCache rebuiltCache(const std::string& hash, const std::string& why) const;
    //! The simulation at the frame to continue from; on a fresh bake, frame 1, written.
    std::unique_ptr<Simulation> startingPoint(FrameCache& cache);
    Outcome bakeFrames(Simulation& simulation, FrameCache& cache, Interrupter& interrupter,
                       int lastFrame);
    void recordFailure(FrameCache& cache, const Error& error) const;
    Simulation::Advance bakeFrame(Simulation& simulation, FrameCache& cache,
                                  Interrupter& interrupter, BakeProgress progress);

    Scene scene_;
    BakeOptions options_;
    ProgressCallback onProgress_;
    FrameCallback onFrame_;
    MessageCallback onMessage_;
};

} // namespace airtrap
