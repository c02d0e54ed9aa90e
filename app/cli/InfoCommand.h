#pragma once
// `airtrap-cli info DIR [--frame N] [--json]`: what one cached frame holds (default: the last good
// frame), as text or as the JSON object of DESIGN §5.
#include "Command.h"

#include <string>

namespace airtrap::cli {

class InfoCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    std::string cacheDir_;
    int frame_ = 0;
    bool json_ = false;
};

} // namespace airtrap::cli
