#pragma once
// Slurm, as `farm` uses it (docs/FARM.md): sbatch with --parsable to submit a job script and
// learn its id, squeue for the jobs queued or running, sacct where the cluster keeps accounting,
// scancel. Every call passes its arguments as they are (ChildProcess): nothing goes through a
// shell. A missing command or a controller that does not answer → SchedulerError with the
// scheduler's own one-line reason.
#include "FarmJob.h"
#include "JobState.h"

#include <map>
#include <string>
#include <vector>

namespace airtrap::cli {

class SlurmScheduler {
public:
    //! SchedulerError unless sbatch, squeue and scancel are on the PATH.
    static void requireCommands();

    //! The sbatch command line that submits `job`: its log, its array, `afterok` (or `afterany`)
    //! on the ids of `dependencies`, its own options, then `extraOptions` (the user's
    //! `--sbatch`).
    static std::vector<std::string> submitArguments(const FarmJob& job, const std::string& log,
                                                    const std::vector<std::string>& dependencies,
                                                    const std::vector<std::string>& extraOptions);
    //! Runs `arguments` (from submitArguments) and returns the new job's id.
    static std::string submit(const std::vector<std::string>& arguments);
    //! Cancels `ids` (quietly: jobs already ended are no error).
    static void cancel(const std::vector<std::string>& ids);

    //! The queued and running jobs and array tasks of `ids`, keyed by their own id ("123",
    //! "123_4"). SchedulerError when squeue fails.
    static std::map<std::string, JobState> queued(const std::vector<std::string>& ids);
    //! What accounting says of `ids` and their tasks; empty when the cluster keeps none.
    static std::map<std::string, JobState> accounted(const std::vector<std::string>& ids);
};

} // namespace airtrap::cli
