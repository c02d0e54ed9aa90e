#include "FarmCancelCommand.h"

#include "FarmLayout.h"
#include "FarmListing.h"
#include "SlurmScheduler.h"
#include "core/Error.h"

#include <filesystem>
#include <iostream>
#include <set>

namespace airtrap::cli {

void FarmCancelCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("cancel", "Cancel the queued and running jobs of a farm "
                                           "submission");
    app_->add_option("DIR", dir_, "The --out folder of farm submit")->required();
}

ExitCode FarmCancelCommand::run() {
    const FarmLayout layout{std::filesystem::absolute(dir_)};
    std::error_code error;
    if (!std::filesystem::exists(layout.wedgesFile(), error))
        throw Error(ErrorKind::InvalidInput, dir_ + " holds no farm submission (no wedges.json)");
    const std::vector<std::string> ids = FarmListing::read(layout.wedgesFile().string()).jobIds();
    SlurmScheduler::requireCommands();
    // Only the jobs still waiting or running: the count says what this did.
    std::set<std::string> active;
    for (const auto& [id, state] : SlurmScheduler::queued(ids))
        if (state.active())
            active.insert(id.substr(0, id.find('_')));
    SlurmScheduler::cancel({active.begin(), active.end()});
    std::cout << "cancelled the " << active.size() << " job(s) of " << layout.root.string()
              << " that were still queued or running\n";
    return ExitCode::Success;
}

} // namespace airtrap::cli
