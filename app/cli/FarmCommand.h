#pragma once
// `airtrap-cli farm submit|status|cancel`: bakes, post and export of a scene and its wedges as
// jobs of a Slurm cluster (docs/FARM.md).
#include "Command.h"

#include <memory>
#include <vector>

namespace airtrap::cli {

class FarmCommand : public Command {
public:
    FarmCommand();
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    std::vector<std::unique_ptr<Command>> verbs_;
};

} // namespace airtrap::cli
