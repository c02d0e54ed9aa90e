#include "FarmStatusCommand.h"

#include "cache/FrameCache.h"
#include "core/Error.h"

#include <deque>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

namespace fs = std::filesystem;

namespace airtrap::cli {

namespace {

//! The key=value lines of an exit record; empty when there is none.
std::map<std::string, std::string> readRecord(const fs::path& path) {
    std::map<std::string, std::string> fields;
    std::ifstream in(path);
    std::string line;
    while (std::getline(in, line))
        if (const std::size_t equals = line.find('='); equals != std::string::npos)
            fields[line.substr(0, equals)] = line.substr(equals + 1);
    return fields;
}

//! An array still waiting shows in squeue as one line "123_[2-5]" for all its pending tasks.
const JobState* pendingArray(const std::string& arrayId,
                             const std::map<std::string, JobState>& queued) {
    const auto at = queued.lower_bound(arrayId + "_[");
    return at != queued.end() && at->first.starts_with(arrayId + "_[") ? &at->second : nullptr;
}

int framesCached(const FarmWedge& entry) {
    if (!FrameCache::isCache(entry.folder))
        return 0;
    try {
        int count = 0;
        for (const int frame : FrameCache::open(entry.folder).frames())
            count += frame >= entry.firstFrame && frame <= entry.lastFrame ? 1 : 0;
        return count;
    } catch (const Error&) {
        return -1;
    }
}

//! End states Slurm sets itself: the job did not end by its own exit.
bool endedBySlurm(const std::string& state) {
    for (const char* end :
         {"TIMEOUT", "NODE_FAIL", "OUT_OF_MEMORY", "BOOT_FAIL", "DEADLINE", "PREEMPTED"})
        if (state == end)
            return true;
    return false;
}

//! `base` with the members of `more` added.
nlohmann::json with(nlohmann::json base, const nlohmann::json& more) {
    base.update(more);
    return base;
}

} // namespace

void FarmStatusCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("status", "Show the jobs of a farm submission and how far each "
                                           "wedge is");
    app_->add_option("DIR", dir_, "The --out folder of farm submit")->required();
    app_->add_flag("--json", json_, "Print the status as JSON");
    app_->add_option("--lines", lines_, "Log lines shown per failed task (default 10)")
        ->check(CLI::Range(0, 10000));
}

std::string FarmStatusCommand::tail(const std::string& path) const {
    std::ifstream in(path);
    std::deque<std::string> last;
    std::string line;
    while (std::getline(in, line)) {
        last.push_back(line);
        if (int(last.size()) > lines_)
            last.pop_front();
    }
    std::string text;
    for (const std::string& kept : last)
        text += kept + "\n";
    return text;
}

nlohmann::json FarmStatusCommand::recordState(const std::map<std::string, std::string>& record,
                                              const std::string& log) const {
    const auto field = [&](const char* key) {
        const auto at = record.find(key);
        return at == record.end() ? std::string() : at->second;
    };
    const int exit = std::atoi(field("exit").empty() ? "-1" : field("exit").c_str());
    nlohmann::json state = {{"state", exit == 0     ? "COMPLETED"
                                      : exit == 75  ? "PREEMPTED"
                                      : exit == 130 ? "CANCELLED"
                                                    : "FAILED"},
                            {"exit", exit},
                            {"host", field("host")},
                            {"started", field("started")},
                            {"ended", field("ended")}};
    if (exit != 0)
        state["log_tail"] = tail(log);
    return state;
}

nlohmann::json FarmStatusCommand::taskState(const FarmJob& job, int task, const Sources& sources,
                                            const FarmLayout& layout) const {
    const std::string id = task < 0 ? job.id : job.id + "_" + std::to_string(task);
    const std::string log = (layout.logsDir() / (job.key + "-" + id + ".log")).string();
    const nlohmann::json state = {{"id", id}, {"log", log}};
    const std::map<std::string, std::string> record = ownRecord(job, task, layout);
    const auto queued = sources.queued.find(id);
    if (queued != sources.queued.end()) {
        const JobState& scheduler = queued->second;
        const nlohmann::json said = {{"state", scheduler.state}, {"reason", scheduler.reason}};
        // While it waits or runs, the queue knows best (a requeued job's record is of its last
        // run); when Slurm itself ended it (a time limit, a lost node), so does its end state.
        if (scheduler.active() || record.empty())
            return with(state, said);
        if (endedBySlurm(scheduler.state))
            return with(with(state, recordState(record, log)), said);
    }
    const JobState* pending = task >= 0 ? pendingArray(job.id, sources.queued) : nullptr;
    if (record.empty() && pending != nullptr)
        return with(state, {{"state", pending->state}, {"reason", pending->reason}});
    // Once it ended, its record says most: the exit code, the host, when it ran.
    if (!record.empty())
        return with(state, recordState(record, log));
    if (const auto accounted = sources.accounted.find(id); accounted != sources.accounted.end())
        return with(state,
                    {{"state", accounted->second.state}, {"reason", accounted->second.reason}});
    return with(state, {{"state", job.id.empty() ? "NOT SUBMITTED" : "UNKNOWN"},
                        {"reason", job.id.empty() ? "a dry run"
                                                  : "no record: not run yet, or ended without "
                                                    "one, and Slurm no longer lists it"}});
}

std::map<std::string, std::string> FarmStatusCommand::ownRecord(const FarmJob& job, int task,
                                                                const FarmLayout& layout) const {
    std::map<std::string, std::string> record = readRecord(layout.record(job.key, task));
    // A record of an earlier submission into this folder (a script run by hand, a job this
    // submission replaced) is not this job's.
    const char* idField = task < 0 ? "job" : "array_job";
    if (!record.empty() && (!record.contains(idField) || record.at(idField) != job.id))
        record.clear();
    return record;
}

nlohmann::json FarmStatusCommand::jobState(const FarmJob& job, const Sources& sources,
                                           const FarmLayout& layout) const {
    nlohmann::json state = {{"key", job.key}, {"stage", job.stage}, {"id", job.id}};
    if (!job.isArray())
        return with(state, taskState(job, -1, sources, layout));
    nlohmann::json tasks = nlohmann::json::array();
    for (int task = 0; task < int(job.frameChunks.size()); ++task)
        tasks.push_back(with(taskState(job, task, sources, layout),
                             {{"task", task}, {"frames", job.frameChunks[std::size_t(task)]}}));
    return with(state, {{"tasks", tasks}});
}

nlohmann::json FarmStatusCommand::wedgeState(const FarmWedge& entry, const Sources& sources,
                                             const FarmLayout& layout) const {
    nlohmann::json values = nlohmann::json::object();
    for (std::size_t i = 0; i < entry.wedge.keys.size(); ++i)
        values[entry.wedge.keys[i]] = entry.wedge.values[i];
    nlohmann::json jobs = nlohmann::json::array();
    for (const FarmJob& job : entry.jobs)
        jobs.push_back(jobState(job, sources, layout));
    return {{"name", entry.wedge.name},
            {"values", values},
            {"folder", entry.folder},
            {"frames_cached", framesCached(entry)},
            {"frames", entry.lastFrame - entry.firstFrame + 1},
            {"jobs", jobs}};
}

void FarmStatusCommand::printJobs(const nlohmann::json& jobs) const {
    std::vector<nlohmann::json> failed;
    for (const nlohmann::json& job : jobs) {
        const std::vector<nlohmann::json> tasks =
            job.contains("tasks") ? job["tasks"].get<std::vector<nlohmann::json>>()
                                  : std::vector<nlohmann::json>{job};
        std::map<std::string, int> counts;
        for (const nlohmann::json& task : tasks) {
            ++counts[task["state"].get<std::string>()];
            if (task.contains("log_tail"))
                failed.push_back(task);
        }
        std::cout << "  " << job["stage"].get<std::string>() << ' ' << job["id"].get<std::string>()
                  << ':';
        for (const auto& [state, count] : counts)
            std::cout << ' ' << (tasks.size() > 1 ? std::to_string(count) + " " : "") << state;
        if (tasks.size() == 1 && tasks.front().contains("reason") &&
            tasks.front()["reason"] != "None")
            std::cout << " (" << tasks.front()["reason"].get<std::string>() << ')';
        std::cout << '\n';
    }
    for (const nlohmann::json& task : failed) {
        std::cout << "  job " << task["id"].get<std::string>() << " ended with exit "
                  << task["exit"].get<int>() << "; " << task["log"].get<std::string>()
                  << " ends:\n";
        std::istringstream lines(task["log_tail"].get<std::string>());
        for (std::string line; std::getline(lines, line);)
            std::cout << "    | " << line << '\n';
    }
}

void FarmStatusCommand::print(const nlohmann::json& status) const {
    for (const nlohmann::json& wedge : status["wedges"]) {
        std::cout << "wedge " << wedge["name"].get<std::string>() << ": "
                  << wedge["frames_cached"].get<int>() << " of " << wedge["frames"].get<int>()
                  << " frame(s) cached in " << wedge["folder"].get<std::string>() << '\n';
        printJobs(wedge["jobs"]);
    }
    if (!status["final_jobs"].empty()) {
        std::cout << "after every wedge:\n";
        printJobs(status["final_jobs"]);
    }
}

ExitCode FarmStatusCommand::run() {
    const FarmLayout layout{fs::absolute(dir_)};
    std::error_code error;
    if (!fs::exists(layout.wedgesFile(), error))
        throw Error(ErrorKind::InvalidInput,
                    dir_ +
                        " holds no farm submission (no wedges.json); submit with airtrap-cli "
                        "farm submit SCENE --out " +
                        dir_);
    const FarmListing listing = FarmListing::read(layout.wedgesFile().string());
    const std::vector<std::string> ids = listing.jobIds();
    Sources sources;
    if (!ids.empty()) {
        sources.queued = SlurmScheduler::queued(ids);
        sources.accounted = SlurmScheduler::accounted(ids);
    }
    nlohmann::json status = {{"folder", layout.root.string()}, {"wedges", nlohmann::json::array()}};
    for (const FarmWedge& entry : listing.wedges)
        status["wedges"].push_back(wedgeState(entry, sources, layout));
    status["final_jobs"] = nlohmann::json::array();
    for (const FarmJob& job : listing.finalJobs)
        status["final_jobs"].push_back(jobState(job, sources, layout));
    if (json_)
        std::cout << status.dump(2) << '\n';
    else
        print(status);
    return ExitCode::Success;
}

} // namespace airtrap::cli
