#pragma once
// How a program ChildProcess ran ended, and what it printed.
#include <string>

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

} // namespace airtrap::cli
