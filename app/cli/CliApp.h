#pragma once
// The command tree of airtrap-cli: parses the command line, runs the chosen verb, and turns every
// failure into one `airtrap-cli: <message>` line on stderr and an exit code (ExitCode.h).
#include "Command.h"

#include <CLI/CLI.hpp>
#include <memory>
#include <optional>
#include <vector>

namespace airtrap::cli {

class CliApp {
public:
    CliApp();
    //! Returns the process exit code.
    int run(int argc, char** argv);

    //! Prints `message` on stderr, each of its lines as `airtrap-cli: <line>`.
    static void printError(const std::string& message);

private:
    //! Parses; returns an exit code when there is nothing more to do (help, usage error).
    std::optional<ExitCode> parse(int argc, char** argv);
    //! The one-line reason for a parse error.
    std::string usageMessage(const CLI::ParseError& error, int argc, char** argv) const;
    ExitCode runChosen();

    CLI::App app_;
    std::vector<std::unique_ptr<Command>> commands_;
};

} // namespace airtrap::cli
