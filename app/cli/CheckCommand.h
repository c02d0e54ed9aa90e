#pragma once
// `airtrap-cli check DIR`: verifies everything a cache folder holds (the manifest, every frame,
// every post result and sub-grid file) and says, for each damaged file, the command that
// repairs it without losing the good ones (docs/CLI.md "check").
#include "Command.h"

#include <string>
#include <vector>

namespace airtrap {
class FrameCache;
}

namespace airtrap::cli {

class CheckCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    //! What one part of the folder held: how many files were verified, and each damage found.
    struct Findings {
        int verified = 0;
        std::vector<std::string> damaged;
        std::vector<std::string> notes; //!< worth knowing, not damage
    };

    //! The manifest's record of the scene (its JSON was read by FrameCache::open).
    Findings checkManifest(const FrameCache& cache) const;
    Findings checkFrames(const FrameCache& cache) const;
    Findings checkPostResults() const;
    Findings checkSubgridFiles() const;
    //! Prints one part's findings and the way on for them; returns whether it found damage.
    bool report(const char* what, const Findings& findings, const std::string& wayOn) const;

    std::string cacheDir_;
};

} // namespace airtrap::cli
