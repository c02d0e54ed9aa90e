#include "PostCommand.h"

#include "CacheScene.h"
#include "FrameRange.h"
#include "ProgressLine.h"
#include "SignalStopper.h"
#include "cache/FrameCache.h"
#include "core/Error.h"
#include "core/ThreadLimit.h"
#include "post/PostStage.h"

#include <cmath>
#include <cstdio>
#include <iostream>
#include <unistd.h>

namespace airtrap::cli {

void PostCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand(
        "post",
        "Make the water's free-surface mesh and volume and the sub-grid bubbles of a baked cache "
        "(kept in DIR/post)");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
    app_->add_option("--frames", framesText_, "Frames: A:B, A:, :B or N (default: all)");
    app_->add_option("--set", overrides_,
                     "Change a render setting for this run, e.g. surface_mesh.smoothing=8 "
                     "(surface_mesh.*, bubble_mesh.* and subgrid_bubbles.* only)");
    app_->add_option("--threads,-j", threads_, "Worker threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    app_->add_flag("--quiet,-q", quiet_, "No progress line and no summary");
    app_->add_option("--part", part_,
                     "For runs over other frames at the same time (a farm's job array): list "
                     "results in post/parts/NAME.json, merged by the next run without --part; "
                     "leaves out the sub-grid pass");
    app_->add_flag("--no-subgrid", noSubgrid_,
                   "Leave out the sub-grid bubbles (they go in frame order: run post again "
                   "without it over the whole range)");
}

void PostCommand::summariseSubgrid(const SubgridReport& report) const {
    std::cout << "sub-grid bubbles: " << report.made << " frame(s) made";
    if (report.alreadyCurrent > 0)
        std::cout << ", " << report.alreadyCurrent << " already current";
    if (report.lastFrame > 0)
        std::cout << "; " << report.lastFrameBubbles << " in frame " << report.lastFrame;
    char seconds[32];
    std::snprintf(seconds, sizeof seconds, "%.2f", report.seconds);
    std::cout << " (" << seconds << " s)\n";
}

ExitCode PostCommand::summarise(const PostReport& report, const std::string& storeDir) const {
    for (const std::string& damage : report.replacedLists)
        std::cerr << "note: " << damage << "; started afresh, its results are made again\n";
    for (const std::string& problem : report.damaged)
        std::cerr << "warning: " << problem << "; frame skipped\n";
    if (report.stopped) {
        std::cerr << "stopped after " << report.made
                  << " frame(s); run post again to finish (finished frames are kept)\n";
        return SignalStopper::stoppedExitCode();
    }
    if (!quiet_) {
        char perFrame[32];
        std::snprintf(perFrame, sizeof perFrame, "%.2f", report.secondsPerFrame);
        std::cout << "post: " << report.made << " frame(s) made";
        if (report.alreadyCurrent > 0)
            std::cout << ", " << report.alreadyCurrent << " already current";
        if (report.made > 0)
            std::cout << " (" << perFrame << " s per frame)";
        if (report.mergedFrames > 0)
            std::cout << ", " << report.mergedFrames << " listed from part runs";
        std::cout << " in " << ProgressLine::clock(report.seconds) << " into " << storeDir << '\n';
        if (part_.empty() && !noSubgrid_)
            summariseSubgrid(report.subgrid);
    }
    if (!report.damaged.empty())
        throw Error(ErrorKind::CacheCorrupt, std::to_string(report.damaged.size()) +
                                                 " damaged frame(s) skipped; bake --resume "
                                                 "or re-bake them, then run post again");
    return ExitCode::Success;
}

ExitCode PostCommand::run() {
    const FrameCache cache = FrameCache::open(cacheDir_);
    const Scene scene = cacheScene(cache, overrides_);
    const std::vector<int> frames =
        FrameRange::selectListed(cache.frames(), framesText_, cache.directory());
    const ThreadLimit limit(threads_);
    PostStage stage(cache, scene, PostOptions{.part = part_, .subgrid = !noSubgrid_});

    const bool inPlace = !quiet_ && ::isatty(STDERR_FILENO);
    const auto total = frames.size();
    Interrupter interrupter([&](const std::string& stageName, double percent) {
        if (quiet_)
            return;
        std::cerr << (inPlace ? "\r" : "") << stageName << ": ";
        // The sub-grid pass also walks the frames before the chosen ones: its share is a percent.
        if (stageName == "post")
            std::cerr << std::lround(percent * double(total) / 100.0) << " of " << total
                      << " frame(s)";
        else
            std::cerr << std::lround(percent) << " %   ";
        std::cerr << (inPlace ? "" : "\n") << std::flush;
    });
    const SignalStopper stopper(interrupter);
    const PostReport report = stage.run(frames, interrupter);
    if (inPlace)
        std::cerr << '\n';
    return summarise(report, stage.store().directory());
}

} // namespace airtrap::cli
