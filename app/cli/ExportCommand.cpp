#include "ExportCommand.h"

#include "FrameRange.h"
#include "SignalStopper.h"
#include "cache/FrameCache.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "io/PlyExporter.h"

#include <filesystem>
#include <iostream>

namespace airtrap::cli {

void ExportCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("export", "Write cached frames as files other tools read");
    app_->add_option("DIR", cacheDir_, "Cache folder")->required();
    app_->add_option("--format", format_,
                     "ply: particle points (particles_0001.ply ...); obj and vdb come later")
        ->required()
        ->check(CLI::IsMember({"ply", "obj", "vdb"}));
    app_->add_option("--out,-o", outDir_, "Output folder (created if missing)")->required();
    app_->add_option("--frames", framesText_, "Frames to export: A:B, A:, :B or N (default: all)");
    app_->add_flag("--quiet,-q", quiet_, "No summary line");
}

std::vector<int> ExportCommand::selectFrames(const FrameCache& cache) const {
    const std::vector<int> listed = cache.frames();
    if (listed.empty())
        throw Error(ErrorKind::InvalidInput, cache.directory() + " holds no frames yet");
    const FrameRange range =
        FrameRange::parse(framesText_, listed.back(), "the last frame in " + cache.directory());
    std::vector<int> selected;
    for (const int frame : listed)
        if (range.contains(frame))
            selected.push_back(frame);
    if (selected.empty())
        throw Error(ErrorKind::InvalidInput, "--frames " + framesText_ + ": " + cache.directory() +
                                                 " holds none of these frames");
    return selected;
}

void ExportCommand::createOutputFolder() const {
    std::error_code error;
    std::filesystem::create_directories(outDir_, error);
    if (error)
        throw Error(ErrorKind::Io,
                    AtomicFile::errorMessage("cannot create folder", outDir_, error.value()));
}

bool ExportCommand::exportFrame(const FrameCache& cache, int frame) const {
    FrameData data;
    try {
        data = cache.readFrame(frame);
    } catch (const Error& error) {
        if (error.kind() != ErrorKind::CacheCorrupt)
            throw;
        std::cerr << "warning: " << error.what() << "; frame " << frame << " skipped\n";
        return false;
    }
    const std::vector<std::string> comments = {
        "Airtrap " AIRTRAP_VERSION,
        "frame " + std::to_string(frame) + ", t = " + std::to_string(data.state.time) + " s",
        "metres, Y up; vx vy vz in m/s, density in kg/m^3"};
    PlyExporter::write(outDir_ + "/" + PlyExporter::fileName(frame), data.state.fluid, comments);
    return true;
}

ExitCode ExportCommand::run() {
    // Checked before anything is opened or created: a later format must not leave a stray folder.
    if (format_ != "ply")
        throw Error(ErrorKind::NotAvailable, "export format '" + format_ +
                                                 "' is not available yet (it needs the post "
                                                 "stage); use --format ply");
    const FrameCache cache = FrameCache::open(cacheDir_);
    const std::vector<int> frames = selectFrames(cache);
    createOutputFolder();

    Interrupter interrupter;
    const SignalStopper stopper(interrupter);
    std::vector<int> skipped;
    int written = 0;
    for (const int frame : frames) {
        if (interrupter.stopRequested()) {
            std::cerr << "stopped after " << written << " file(s) in " << outDir_ << '\n';
            return ExitCode::Stopped;
        }
        if (exportFrame(cache, frame))
            ++written;
        else
            skipped.push_back(frame);
    }
    if (!quiet_)
        std::cout << "exported " << written << " frame(s) to " << outDir_ << " ("
                  << PlyExporter::fileName(frames.front()) << " … "
                  << PlyExporter::fileName(frames.back()) << ")\n";
    if (skipped.empty())
        return ExitCode::Success;
    std::string list;
    for (const int frame : skipped)
        list += (list.empty() ? "" : ", ") + std::to_string(frame);
    throw Error(ErrorKind::CacheCorrupt,
                std::to_string(skipped.size()) + " damaged frame(s) skipped: " + list);
}

} // namespace airtrap::cli
