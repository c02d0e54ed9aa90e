#pragma once
// One job of a farm submission (docs/FARM.md): a job script and what the scheduler needs to
// run it — its array size, the jobs it waits for, its own options. FarmSubmitCommand plans them,
// FarmScriptWriter writes their scripts, SlurmScheduler submits them.
#include <string>
#include <vector>

namespace airtrap::cli {

struct FarmJob {
    std::string key;    //!< unique in the submission: "<stage>-<wedge index>", e.g. "bake-0"
    std::string stage;  //!< bake, post, post-merge, export, export-listing
    std::string wedge;  //!< the wedge's name
    std::string script; //!< absolute path of its job script
    std::vector<std::string> frameChunks; //!< "A:B" per array task; empty: a single job
    std::vector<std::string> after;       //!< keys of the jobs that must end first
    //! False: those jobs must succeed (afterok). True: their ending is enough (afterany), for a
    //! job that reports on all of them (the contact sheet).
    bool afterAny = false;
    std::vector<std::string> schedulerOptions; //!< its own sbatch options (requeue, signal, cpus)
    std::string id;                            //!< the scheduler's job id, once submitted

    bool isArray() const { return !frameChunks.empty(); }
};

} // namespace airtrap::cli
