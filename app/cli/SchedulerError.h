#pragma once
// A scheduler that is missing, refuses a job or does not answer (`farm`); CliApp reports its
// one-line reason and exits with ExitCode::Scheduler.
#include <stdexcept>
#include <string>

namespace airtrap::cli {

class SchedulerError : public std::runtime_error {
public:
    explicit SchedulerError(const std::string& reason) : std::runtime_error(reason) {}
};

} // namespace airtrap::cli
