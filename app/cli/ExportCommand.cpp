#include "ExportCommand.h"

#include "CacheScene.h"
#include "FrameRange.h"
#include "SignalStopper.h"
#include "cache/FrameCache.h"
#include "core/Error.h"
#include "io/SequenceExporter.h"

#include <cmath>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

namespace airtrap::cli {

namespace {

std::vector<std::string> formatNames() {
    std::vector<std::string> names;
    for (ExportFormat format : kExportFormats)
        names.emplace_back(exportFormatName(format));
    return names;
}

std::vector<std::string> upAxisNames() {
    return {std::string(upAxisName(UpAxis::Y)), std::string(upAxisName(UpAxis::Z))};
}

} // namespace

void ExportCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("export", "Write cached frames as files renderers read");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
    app_->add_option("--format", format_,
                     "obj: water_/bubbles_/subgrid_/bodies_0001.obj meshes; vdb: "
                     "fluid_0001.vdb (surface, density, vel); ply: particles_/bubbles_/"
                     "subgrid_0001.ply points. obj and vdb need `post` first")
        ->required()
        ->check(CLI::IsMember(formatNames()));
    app_->add_option("--out,-o", outDir_, "Output folder (created if missing)")->required();
    app_->add_option("--frames", framesText_, "Frames to export: A:B, A:, :B or N (default: all)");
    app_->add_option("--up", up_, "Up axis of the files: y (default) or z")
        ->check(CLI::IsMember(upAxisNames()));
    app_->add_option("--set", overrides_,
                     "Change a render setting for this export, e.g. bubble_mesh.magnitude=0.2 "
                     "(surface_mesh.*, bubble_mesh.* and subgrid_bubbles.* only)");
    app_->add_flag("--quiet,-q", quiet_, "No progress line and no summary");
    CLI::Option* noListing =
        app_->add_flag("--no-listing", noListing_,
                       "Write the frames but not export.json, for runs over other frames into "
                       "the same folder at once (a farm's job array)");
    app_->add_flag("--listing-only", listingOnly_,
                   "Write no frame: list the files of this format and --frames already in --out "
                   "in export.json (after --no-listing runs)")
        ->excludes(noListing);
}

ExitCode ExportCommand::summarise(const ExportReport& report) const {
    if (report.stopped) {
        std::cerr << "stopped after " << report.framesWritten << " frame(s) in " << outDir_ << '\n';
        return SignalStopper::stoppedExitCode();
    }
    if (!quiet_ && listingOnly_)
        std::cout << "listed " << report.files.size() << " file(s) in " << outDir_
                  << "/export.json\n";
    else if (!quiet_ && !report.files.empty())
        std::cout << "exported " << report.framesWritten << " frame(s), " << report.files.size()
                  << " file(s) to " << outDir_ << " (" << report.files.front() << " … "
                  << report.files.back() << ")\n";
    if (report.damaged.empty())
        return ExitCode::Success;
    for (const std::string& problem : report.damaged)
        std::cerr << "warning: " << problem << "; frame skipped\n";
    throw Error(ErrorKind::CacheCorrupt,
                std::to_string(report.damaged.size()) + " damaged frame(s) skipped");
}

ExitCode ExportCommand::run() {
    const FrameCache cache = FrameCache::open(cacheDir_);
    const Scene scene = cacheScene(cache, overrides_);
    const std::vector<int> frames =
        FrameRange::selectListed(cache.frames(), framesText_, cache.directory());
    const ExportOptions options{.format = SequenceExporter::parseFormat(format_),
                                .outDir = outDir_,
                                .up = upAxisNamed(up_).value_or(UpAxis::Y),
                                .listing = listingOnly_ ? ExportListingMode::Only
                                           : noListing_ ? ExportListingMode::Leave
                                                        : ExportListingMode::Update};
    SequenceExporter exporter(cache, scene, options);
    // The same progress line as post's: a VDB export of a long bake takes minutes.
    const bool inPlace = !quiet_ && ::isatty(STDERR_FILENO);
    const auto total = frames.size();
    Interrupter interrupter([&](const std::string& stage, double percent) {
        if (quiet_)
            return;
        std::cerr << (inPlace ? "\r" : "") << stage << ": "
                  << std::lround(percent * double(total) / 100.0) << " of " << total << " frame(s)"
                  << (inPlace ? "" : "\n") << std::flush;
    });
    const SignalStopper stopper(interrupter);
    const ExportReport report = exporter.run(frames, interrupter);
    if (inPlace)
        std::cerr << '\n';
    return summarise(report);
}

} // namespace airtrap::cli
