#include "FarmCommand.h"

#include "FarmCancelCommand.h"
#include "FarmStatusCommand.h"
#include "FarmSubmitCommand.h"

namespace airtrap::cli {

FarmCommand::FarmCommand() {
    verbs_.push_back(std::make_unique<FarmSubmitCommand>());
    verbs_.push_back(std::make_unique<FarmStatusCommand>());
    verbs_.push_back(std::make_unique<FarmCancelCommand>());
}

void FarmCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand(
        "farm", "Bake, post and export a scene and its wedges as Slurm jobs (docs/FARM.md)");
    app_->require_subcommand(1);
    for (const auto& verb : verbs_)
        verb->addTo(*app_);
}

ExitCode FarmCommand::run() {
    for (const auto& verb : verbs_)
        if (verb->chosen())
            return verb->run();
    return ExitCode::Usage;
}

} // namespace airtrap::cli
