#pragma once
// `airtrap-cli farm cancel DIR`: cancels every job of a farm submission that is still queued or
// running. A bake cancelled mid-frame keeps its cache consistent; submitting again continues it.
#include "Command.h"

#include <string>

namespace airtrap::cli {

class FarmCancelCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    std::string dir_;
};

} // namespace airtrap::cli
