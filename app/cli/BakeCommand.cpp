#include "BakeCommand.h"

#include "CliApp.h"
#include "ProgressLine.h"
#include "SceneLoader.h"
#include "ShellQuote.h"
#include "SignalStopper.h"
#include "bake/Baker.h"
#include "cache/FrameCache.h"
#include "core/Error.h"
#include "core/ThreadLimit.h"

#include <chrono>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace airtrap::cli {

namespace {

//! "frame 3" or "frames 1–7", followed by `singular` or `plural` ("is"/"are").
std::string frameSpan(int first, int last, const char* singular = "", const char* plural = "") {
    return first == last ? "frame " + std::to_string(first) + singular
                         : "frames " + std::to_string(first) + "–" + std::to_string(last) + plural;
}

std::string seconds(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%.2f s", value);
    return text;
}

} // namespace

void BakeCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("bake", "Simulate a scene into a frame cache folder");
    app_->add_option("SCENE", scenePath_, "Scene file (JSON)")->required();
    app_->add_option("--out,-o", outDir_, "Cache folder (created if missing)")->required();
    app_->add_option("--frames", framesText_,
                     "Frames to bake: A:B, A:, :B or N (default: 1 to frames.end_frame). A start "
                     "after 1 continues the cache from frame A−1");
    CLI::Option* resume =
        app_->add_flag("--resume", resume_,
                       "Continue the cache in --out from its last good frame (or start it); "
                       "with --frames A:B, A is only the range's start");
    app_->add_flag("--overwrite", overwrite_, "Replace the cache in --out (only its own files)")
        ->excludes(resume);
    app_->add_option("--threads,-j", threads_, "Worker threads (0 = all cores)")
        ->check(CLI::Range(0, 4096));
    app_->add_option("--set", overrides_,
                     "Override a scene value, e.g. solver.particle_spacing=0.02 (repeatable)")
        ->allow_extra_args(false);
    app_->add_flag("--quiet,-q", quiet_, "No progress line");
}

int BakeCommand::lastCachedFrame() const {
    try {
        const std::vector<int> frames = FrameCache::open(outDir_).frames();
        return frames.empty() ? 0 : frames.back();
    } catch (const Error&) {
        return 0;
    }
}

void BakeCommand::refuseRecompute(const FrameRange& range) const {
    if (!FrameCache::isCache(outDir_))
        throw Error(ErrorKind::InvalidInput,
                    "--frames " + framesText_ + " continues the cache in " + outDir_ +
                        " from frame " + std::to_string(range.first() - 1) +
                        ", but that folder holds no Airtrap cache; bake from frame 1 first");
    const int newest = lastCachedFrame();
    if (newest >= range.first() && !overwrite_)
        throw Error(ErrorKind::InvalidInput,
                    outDir_ + " already holds " + frameSpan(range.first(), newest) +
                        "; add --overwrite to recompute from frame " +
                        std::to_string(range.first()) + " (every cached frame after " +
                        std::to_string(range.first() - 1) + " is replaced)");
}

void BakeCommand::checkCacheFolder(const FrameRange& range) const {
    // --resume makes the frames up to B whole from the first missing or damaged one, whatever
    // the start frame says, so the same command line starts, continues or finishes a bake (a
    // farm's requeued job runs its script again unchanged).
    if (resume_)
        return;
    if (range.first() > 1) {
        refuseRecompute(range);
        return;
    }
    if (!resume_ && !overwrite_ && FrameCache::isCache(outDir_))
        throw Error(ErrorKind::InvalidInput,
                    outDir_ + " already holds an Airtrap cache; continue it with --resume, "
                              "replace it with --overwrite, or choose another --out folder");
}

std::string BakeCommand::resumeCommand(const FrameRange& range) const {
    std::string command =
        "airtrap-cli bake " + shellQuote(scenePath_) + " --out " + shellQuote(outDir_);
    if (range.firstGiven())
        command += " --frames " + shellQuote(framesText_);
    else if (range.lastGiven())
        command += " --frames :" + std::to_string(range.last());
    // The overrides are part of the scene: without them the parameter hash would not match.
    for (const std::string& assignment : overrides_)
        command += " --set " + shellQuote(assignment);
    return command + " --resume";
}

ExitCode BakeCommand::explainFailure(const Error& error, ProgressLine& progress) const {
    progress.finish();
    CliApp::printError(error.what());
    const int newest = lastCachedFrame();
    if (newest > 0 && error.kind() == ErrorKind::SimulationBlowUp)
        std::cerr << "note: " << frameSpan(1, newest, " is", " are") << " kept in " << outDir_
                  << '\n';
    else if (newest > 0 && error.kind() == ErrorKind::Io)
        std::cerr << "note: the cache in " << outDir_ << " is consistent (" << frameSpan(1, newest)
                  << "); once the problem is fixed, continue with --resume\n";
    else if (error.kind() == ErrorKind::Io)
        std::cerr << "note: no frame is cached in " << outDir_
                  << " yet; once the problem is fixed, continue with --resume (it starts the "
                     "bake when there is nothing to continue)\n";
    return exitCodeFor(error.kind());
}

ExitCode BakeCommand::summarise(const ProgressLine& progress, double wallSeconds) const {
    if (progress.framesDone() == 0) {
        std::cout << "nothing to do: " << outDir_ << " already holds frames up to "
                  << lastCachedFrame() << '\n';
        return ExitCode::Success;
    }
    const double rate =
        progress.stepSeconds() > 0.0 ? double(progress.steps()) / progress.stepSeconds() : 0.0;
    char mean[32];
    std::snprintf(mean, sizeof mean, "%.0f", rate);
    std::cout << "baked " << frameSpan(progress.firstFrameDone(), progress.lastFrameDone())
              << " in " << seconds(wallSeconds) << " (" << mean << " steps/s mean) into " << outDir_
              << '\n';
    return ExitCode::Success;
}

ExitCode BakeCommand::run() {
    // First: a farm's warning signal may come while a large scene still loads, and unhandled it
    // would end the process rather than stop it (docs/FARM.md "Preemption and time limits").
    Interrupter interrupter;
    const SignalStopper stopper(interrupter);
    const LoadedScene loaded = SceneLoader::load(scenePath_, overrides_);
    for (const std::string& warning : loaded.warnings)
        std::cerr << "warning: " << warning << '\n';
    for (const std::string& note : loaded.notes)
        std::cerr << "note: " << note << '\n';
    const FrameRange range =
        FrameRange::parse(framesText_, loaded.scene.frames.endFrame, "frames.end_frame");
    checkCacheFolder(range);

    const ThreadLimit limit(threads_);
    const BakeOptions options{.cacheDir = outDir_,
                              .resume = resume_,
                              .overwrite = overwrite_,
                              .firstFrame = range.first() > 1 && !resume_ ? range.first() : 0,
                              .lastFrame = range.last()};
    const ProgressLine::Mode mode = quiet_                    ? ProgressLine::Mode::Silent
                                    : ::isatty(STDERR_FILENO) ? ProgressLine::Mode::InPlace
                                                              : ProgressLine::Mode::PerFrame;
    ProgressLine progress(std::cerr, mode, loaded.scene.frames.fps, range.last(),
                          loaded.scene.bubbles.enabled);
    Baker baker(loaded.scene, options);
    baker.onProgress([&](const BakeProgress& p) { progress.step(p); });
    baker.onFrame([&](int frame, const FrameStats& stats) { progress.frameDone(frame, stats); });
    baker.onMessage([&](const std::string& message) { progress.note("note: " + message); });

    const auto start = std::chrono::steady_clock::now();
    Baker::Outcome outcome;
    try {
        outcome = baker.run(interrupter);
    } catch (const Error& error) {
        return explainFailure(error, progress);
    }
    progress.finish();
    if (outcome == Baker::Outcome::Stopped) {
        std::cerr << "stopped after frame " << lastCachedFrame()
                  << "; resume with: " << resumeCommand(range) << '\n';
        return SignalStopper::stoppedExitCode();
    }
    return summarise(
        progress, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
}

} // namespace airtrap::cli
