#pragma once
// What Slurm says of one job or array task (SlurmScheduler::queued, ::accounted).
#include <string>

namespace airtrap::cli {

//! A job or array task as the scheduler reports it.
struct JobState {
    std::string id;     //!< "123", or "123_4" for task 4 of array 123
    std::string state;  //!< PENDING, RUNNING, COMPLETED, FAILED, CANCELLED, …
    std::string reason; //!< why it waits (squeue), or its exit code (sacct)

    //! Still to run or running (pending, running, completing, suspended, requeued, …).
    bool active() const;
};

} // namespace airtrap::cli
