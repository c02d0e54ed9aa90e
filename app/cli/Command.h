#pragma once
// One verb of airtrap-cli. CliApp registers every verb, parses the command line once, and runs the
// verb that was chosen; the verb throws airtrap::Error for failures CliApp turns into exit codes.
#include "ExitCode.h"

#include <CLI/CLI.hpp>

namespace airtrap::cli {

class Command {
public:
    virtual ~Command() = default;

    //! Adds the verb with its options and arguments to `parent`.
    virtual void addTo(CLI::App& parent) = 0;
    //! Does the work; returns the exit code for outcomes that are not errors (e.g. stopped).
    virtual ExitCode run() = 0;

    //! True when this verb was given on the command line.
    bool chosen() const { return app_ != nullptr && app_->parsed(); }

protected:
    CLI::App* app_ = nullptr;
};

} // namespace airtrap::cli
