#pragma once
// `airtrap-cli farm status DIR [--json] [--lines N]`: each wedge's frames cached and each job's
// (and array task's) state — from squeue while it is queued or running, then from the exit
// record its script left in DIR/farm/records, or from sacct where the cluster keeps accounting;
// the log tail of every failed task (docs/FARM.md "farm status").
#include "Command.h"
#include "FarmLayout.h"
#include "FarmListing.h"
#include "SlurmScheduler.h"

#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace airtrap::cli {

class FarmStatusCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    struct Sources {
        std::map<std::string, JobState> queued;
        std::map<std::string, JobState> accounted;
    };
    //! The state of `job`, or of its array task `task` (≥ 0).
    nlohmann::json taskState(const FarmJob& job, int task, const Sources& sources,
                             const FarmLayout& layout) const;
    //! A task's state from its exit record.
    nlohmann::json recordState(const std::map<std::string, std::string>& record,
                               const std::string& log) const;
    //! The exit record of `job` (task `task`, or −1), if this submission's job wrote it.
    std::map<std::string, std::string> ownRecord(const FarmJob& job, int task,
                                                 const FarmLayout& layout) const;
    nlohmann::json jobState(const FarmJob& job, const Sources& sources,
                            const FarmLayout& layout) const;
    nlohmann::json wedgeState(const FarmWedge& entry, const Sources& sources,
                              const FarmLayout& layout) const;
    void print(const nlohmann::json& status) const;
    //! One line per job (array tasks counted by state), then the log tail of each failed task.
    void printJobs(const nlohmann::json& jobs) const;
    //! The last `lines_` lines of `path`, or "" when it cannot be read.
    std::string tail(const std::string& path) const;

    std::string dir_;
    bool json_ = false;
    int lines_ = 10;
};

} // namespace airtrap::cli
