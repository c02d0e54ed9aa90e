#pragma once
// Runs a program (the scheduler's sbatch, squeue, sacct, scancel) with its arguments passed as
// they are, never through a shell, and collects what it prints.
#include <string>
#include <vector>

namespace airtrap::cli {

struct ChildResult {
    bool started = false; //!< false: the program was not found or could not be run
    int exitCode = -1;    //!< its exit status; 128 + N when signal N ended it
    std::string out;
    std::string err;

    bool succeeded() const { return started && exitCode == 0; }
    //! The first line of `err` (or of `out`), trimmed, for a one-line reason.
    std::string firstErrorLine() const;
};

class ChildProcess {
public:
    //! Runs `argv` (argv[0] looked up on PATH) to its end with stdin from /dev/null.
    static ChildResult run(const std::vector<std::string>& argv);
    //! True when `program` is an executable file on PATH.
    static bool onPath(const std::string& program);
};

} // namespace airtrap::cli
