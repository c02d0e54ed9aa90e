#include "SlurmScheduler.h"

#include "ChildProcess.h"
#include "Joined.h"
#include "SchedulerError.h"

#include <set>
#include <sstream>

namespace airtrap::cli {

namespace {

std::vector<std::string> fields(const std::string& line, char separator) {
    std::vector<std::string> parts;
    std::istringstream stream(line);
    std::string part;
    while (std::getline(stream, part, separator))
        parts.push_back(part);
    return parts;
}

ChildResult call(const std::vector<std::string>& arguments) {
    ChildResult result = ChildProcess::run(arguments);
    if (!result.started)
        throw SchedulerError(arguments.front() + " could not be run: is Slurm's client installed "
                                                 "and on the PATH?");
    return result;
}

} // namespace

bool JobState::active() const {
    for (const char* waitingOrRunning :
         {"PENDING", "CONFIGURING", "RUNNING", "COMPLETING", "SUSPENDED", "REQUEUED",
          "REQUEUE_HOLD", "REQUEUE_FED", "RESIZING", "SIGNALING", "STAGE_OUT", "STOPPED"})
        if (state == waitingOrRunning)
            return true;
    return false;
}

void SlurmScheduler::requireCommands() {
    for (const char* command : {"sbatch", "squeue", "scancel"})
        if (!ChildProcess::onPath(command))
            throw SchedulerError(std::string(command) +
                                 " is not on the PATH: farm needs Slurm's client commands (Debian: "
                                 "apt-get install slurm-client), or use --dry-run");
}

std::vector<std::string>
SlurmScheduler::submitArguments(const FarmJob& job, const std::string& log,
                                const std::vector<std::string>& dependencies,
                                const std::vector<std::string>& extraOptions) {
    std::vector<std::string> arguments = {"sbatch", "--parsable", "--job-name=airtrap-" + job.key,
                                          "--output=" + log};
    if (job.isArray())
        arguments.push_back("--array=0-" + std::to_string(job.frameChunks.size() - 1));
    if (!dependencies.empty()) {
        arguments.push_back(std::string("--dependency=") +
                            (job.afterAny ? "afterany:" : "afterok:") + joined(dependencies, ":"));
        // A job whose afterok can never be met (what it waits for failed) is cancelled rather
        // than left waiting for ever; so every job ends, and the contact sheet after them runs.
        arguments.push_back("--kill-on-invalid-dep=yes");
    }
    arguments.insert(arguments.end(), job.schedulerOptions.begin(), job.schedulerOptions.end());
    arguments.insert(arguments.end(), extraOptions.begin(), extraOptions.end());
    arguments.push_back(job.script);
    return arguments;
}

std::string SlurmScheduler::submit(const std::vector<std::string>& arguments) {
    const ChildResult result = call(arguments);
    // --parsable prints "id" or "id;cluster".
    const std::string id = result.out.substr(0, result.out.find_first_of(";\n"));
    if (!result.succeeded() || id.empty() ||
        id.find_first_not_of("0123456789") != std::string::npos)
        throw SchedulerError("sbatch refused " + arguments.back() + ": " + result.firstErrorLine());
    return id;
}

void SlurmScheduler::cancel(const std::vector<std::string>& ids) {
    if (ids.empty())
        return;
    std::vector<std::string> arguments = {"scancel"};
    arguments.insert(arguments.end(), ids.begin(), ids.end());
    const ChildResult result = call(arguments);
    if (!result.succeeded() && result.err.find("Invalid job id") == std::string::npos)
        throw SchedulerError("scancel failed: " + result.firstErrorLine());
}

std::map<std::string, JobState> SlurmScheduler::queued(const std::vector<std::string>& ids) {
    // All jobs, one line per array task, filtered here: squeue fails for an id that has left
    // the queue, and every job of a submission leaves it in the end.
    const ChildResult result =
        call({"squeue", "--noheader", "--array", "--states=all", "--format=%F|%K|%i|%T|%r"});
    if (!result.succeeded())
        throw SchedulerError("squeue failed: " + result.firstErrorLine());
    const std::set<std::string> wanted(ids.begin(), ids.end());
    std::map<std::string, JobState> states;
    std::istringstream lines(result.out);
    std::string line;
    while (std::getline(lines, line)) {
        const std::vector<std::string> part = fields(line, '|');
        if (part.size() < 5 || !wanted.contains(part[0]))
            continue;
        // %i of a pending array is "123_[0-3]": each pending task counts under it.
        states[part[2]] = JobState{part[2], part[3], part[4]};
    }
    return states;
}

std::map<std::string, JobState> SlurmScheduler::accounted(const std::vector<std::string>& ids) {
    if (ids.empty() || !ChildProcess::onPath("sacct"))
        return {};
    const ChildResult result =
        ChildProcess::run({"sacct", "--noheader", "--parsable2", "--allocations",
                           "--jobs=" + joined(ids, ","), "--format=JobID,State,ExitCode"});
    std::map<std::string, JobState> states;
    if (!result.succeeded())
        return states;
    std::istringstream lines(result.out);
    std::string line;
    while (std::getline(lines, line)) {
        const std::vector<std::string> part = fields(line, '|');
        if (part.size() >= 3)
            states[part[0]] = JobState{part[0], part[1], "exit " + part[2]};
    }
    return states;
}

} // namespace airtrap::cli
