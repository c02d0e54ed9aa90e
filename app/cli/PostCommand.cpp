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
        "Make the water's free-surface mesh and volume of a baked cache (kept in DIR/post)");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
    app_->add_option("--frames", framesText_, "Frames: A:B, A:, :B or N (default: all)");
    app_->add_option("--set", overrides_,
                     "Change a render setting for this run, e.g. surface_mesh.smoothing=8 "
                     "(surface_mesh.* and bubble_mesh.* only)");
    app_->add_option("--threads,-j", threads_, "Worker threads (0 = all cores)")
        ->check(CLI::Range(0, 1024));
    app_->add_flag("--quiet,-q", quiet_, "No progress line and no summary");
}

ExitCode PostCommand::summarise(const PostReport& report, const std::string& storeDir) const {
    for (const std::string& problem : report.damaged)
        std::cerr << "warning: " << problem << "; frame skipped\n";
    if (report.stopped) {
        std::cerr << "stopped after " << report.made
                  << " frame(s); run post again to finish (finished frames are kept)\n";
        return ExitCode::Stopped;
    }
    if (!quiet_) {
        char perFrame[32];
        std::snprintf(perFrame, sizeof perFrame, "%.2f", report.secondsPerFrame);
        std::cout << "post: " << report.made << " frame(s) made";
        if (report.alreadyCurrent > 0)
            std::cout << ", " << report.alreadyCurrent << " already current";
        if (report.made > 0)
            std::cout << " (" << perFrame << " s per frame)";
        std::cout << " in " << ProgressLine::clock(report.seconds) << " into " << storeDir << '\n';
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
    PostStage stage(cache, scene);

    const bool inPlace = !quiet_ && ::isatty(STDERR_FILENO);
    const auto total = frames.size();
    Interrupter interrupter([&](const std::string&, double percent) {
        if (quiet_)
            return;
        const auto done = std::size_t(std::lround(percent * double(total) / 100.0));
        std::cerr << (inPlace ? "\r" : "") << "post: " << done << " of " << total << " frame(s)"
                  << (inPlace ? "" : "\n") << std::flush;
    });
    const SignalStopper stopper(interrupter);
    const PostReport report = stage.run(frames, interrupter);
    if (inPlace)
        std::cerr << '\n';
    return summarise(report, stage.store().directory());
}

} // namespace airtrap::cli
