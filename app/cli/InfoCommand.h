#pragma once
// `airtrap-cli info DIR [--frame N] [--json]`: what one cached frame holds (default: the last good
// frame), as text or as the JSON object of docs/CLI.md; `--bubbles` surveys every frame's bubbles.
#include "Command.h"
#include "cache/FrameCache.h"

#include <string>

namespace airtrap::cli {

class InfoCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    ExitCode surveyBubbles(const FrameCache& cache) const;

    std::string cacheDir_;
    int frame_ = 0;
    bool json_ = false;
    bool bubbles_ = false;
};

} // namespace airtrap::cli
