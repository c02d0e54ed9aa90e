#pragma once
// `airtrap-cli bake SCENE --out DIR [--frames A:B] [--resume] [--overwrite] [--threads N]
// [--set key=value ...] [--quiet]`: runs the same Baker as the editor, with a progress line, and
// stops cleanly on Ctrl-C.
#include "Command.h"
#include "FrameRange.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class ProgressLine;

class BakeCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    //! Refuses, before anything is written, a folder the bake would wrongly create, replace or
    //! continue.
    void checkCacheFolder(const FrameRange& range) const;
    //! A start frame A > 1 continues a cache: it must exist, and replacing its frames from A on
    //! needs --overwrite.
    void refuseRecompute(const FrameRange& range) const;
    //! The newest frame listed in the cache, or 0 (no cache, unreadable manifest).
    int lastCachedFrame() const;
    //! The command that continues this bake, for the user to paste.
    std::string resumeCommand(const FrameRange& range) const;
    //! After a failure: the error, which frames survived and how to go on; the exit code.
    ExitCode explainFailure(const Error& error, ProgressLine& progress) const;
    ExitCode summarise(const ProgressLine& progress, double wallSeconds) const;

    std::string scenePath_;
    std::string outDir_;
    std::string framesText_;
    bool resume_ = false;
    bool overwrite_ = false;
    bool quiet_ = false;
    int threads_ = 0;
    std::vector<std::string> overrides_;
};

} // namespace airtrap::cli
