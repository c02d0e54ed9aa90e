#pragma once
// `airtrap-cli export DIR --format obj|vdb|ply --out OUTDIR [--frames A:B] [--up y|z]
// [--no-listing | --listing-only]`: the
// sequences of docs/CLI.md "export", written by the engine's SequenceExporter (the editor's Export
// dialog uses the same). OBJ and VDB need the post stage's results and refuse, before writing
// anything, frames that lack them.
#include "Command.h"

#include <string>
#include <vector>

namespace airtrap {
struct ExportReport;
}

namespace airtrap::cli {

class ExportCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    ExitCode summarise(const ExportReport& report) const;

    std::string cacheDir_;
    std::string format_;
    std::string outDir_;
    std::string framesText_;
    std::string up_ = "y";
    std::vector<std::string> overrides_;
    bool quiet_ = false;
    bool noListing_ = false;
    bool listingOnly_ = false;
};

} // namespace airtrap::cli
