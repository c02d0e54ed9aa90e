#include "InfoCommand.h"

#include "BubbleCensusReport.h"
#include "InfoReport.h"
#include "cache/FrameCache.h"
#include "core/Error.h"

#include <iostream>
#include <limits>

namespace airtrap::cli {

void InfoCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("info", "Describe one frame of a cache");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
    app_->add_option("--frame", frame_, "Frame to describe (default: the last good frame)")
        // CLI::PositiveNumber's message prints the largest double in full (300 digits).
        ->check(CLI::Range(1, std::numeric_limits<int>::max())
                    .description("frame number, 1 or more")
                    .name("FRAME"));
    app_->add_flag("--json", json_, "Print one JSON object (fields in docs/CLI.md)");
    app_->add_flag("--bubbles", bubbles_,
                   "Survey where the trapped bubbles lived in every frame: in water, floating or "
                   "airborne (docs/VALIDATION.md)")
        ->excludes("--frame");
}

ExitCode InfoCommand::run() {
    const FrameCache cache = FrameCache::open(cacheDir_);
    if (bubbles_)
        return surveyBubbles(cache);
    int frame = frame_;
    if (frame == 0) {
        std::vector<std::string> problems;
        frame = cache.lastGoodFrame(&problems);
        for (const std::string& problem : problems)
            std::cerr << "note: skipping a damaged frame: " << problem << '\n';
        if (cache.frames().empty())
            throw Error(ErrorKind::InvalidInput, cache.directory() + " holds no frames yet");
        if (frame == 0)
            throw Error(ErrorKind::CacheCorrupt,
                        cache.directory() + ": every cached frame is damaged");
    }
    const FrameData data = cache.readFrame(frame);
    const InfoReport report(data, cache.manifest(), cache.directory());
    if (json_)
        std::cout << report.toJson().dump(2) << '\n';
    else
        report.printText(std::cout);
    return ExitCode::Success;
}

ExitCode InfoCommand::surveyBubbles(const FrameCache& cache) const {
    if (cache.frames().empty())
        throw Error(ErrorKind::InvalidInput, cache.directory() + " holds no frames yet");
    const BubbleCensusReport report(cache, std::cerr);
    if (json_)
        std::cout << report.toJson().dump(2) << '\n';
    else
        report.printText(std::cout);
    return ExitCode::Success;
}

} // namespace airtrap::cli
