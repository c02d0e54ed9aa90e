#pragma once
// Runs a program (the scheduler's sbatch, squeue, sacct, scancel) with its arguments passed as
// they are, never through a shell, and collects what it prints.
#include "ChildResult.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class ChildProcess {
public:
    //! Runs `argv` (argv[0] looked up on PATH) to its end with stdin from /dev/null.
    static ChildResult run(const std::vector<std::string>& argv);
    //! True when `program` is an executable file on PATH.
    static bool onPath(const std::string& program);
};

} // namespace airtrap::cli
