#include "CliApp.h"

#include "BakeCommand.h"
#include "CheckCommand.h"
#include "ExportCommand.h"
#include "FarmCommand.h"
#include "InfoCommand.h"
#include "PostCommand.h"
#include "SchedulerError.h"
#include "ValidateCommand.h"
#include "core/Error.h"

#include <csignal>
#include <iostream>
#include <sstream>

namespace airtrap::cli {

CliApp::CliApp()
    : app_("airtrap-cli: bake, inspect and export Airtrap scenes (water with trapped air) "
           "without the editor",
           "airtrap-cli") {
    app_.set_version_flag("--version", "airtrap-cli " AIRTRAP_VERSION);
    app_.require_subcommand(1);
    app_.footer(kExitCodeHelp);
    commands_.push_back(std::make_unique<ValidateCommand>());
    commands_.push_back(std::make_unique<BakeCommand>());
    commands_.push_back(std::make_unique<InfoCommand>());
    commands_.push_back(std::make_unique<ExportCommand>());
    commands_.push_back(std::make_unique<PostCommand>());
    commands_.push_back(std::make_unique<CheckCommand>());
    commands_.push_back(std::make_unique<FarmCommand>());
    for (const auto& command : commands_)
        command->addTo(app_);
}

void CliApp::printError(const std::string& message) {
    std::istringstream lines(message);
    std::string line;
    while (std::getline(lines, line))
        std::cerr << "airtrap-cli: " << line << '\n';
    std::cerr << std::flush;
}

std::string CliApp::usageMessage(const CLI::ParseError& error, int argc, char** argv) const {
    // CLI11 checks required arguments before unknown ones, so "--out is required" would hide the
    // typo that caused it; name the typo instead.
    if (app_.get_subcommands().empty() && argc > 1 && argv[1][0] != '-')
        return "unknown command '" + std::string(argv[1]) +
               "'; the commands are validate, bake, info, post, export, check, farm";
    for (const CLI::App* sub : app_.get_subcommands()) {
        const std::vector<std::string> extra = sub->remaining();
        if (!extra.empty())
            return "unexpected argument '" + extra.front() + "' for " + sub->get_name();
    }
    return error.what();
}

std::optional<ExitCode> CliApp::parse(int argc, char** argv) {
    try {
        app_.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        // --help and --version arrive as "errors" with exit code 0; CLI11 prints them.
        if (error.get_exit_code() == 0) {
            app_.exit(error);
            return ExitCode::Success;
        }
        printError(usageMessage(error, argc, argv) + " (see airtrap-cli --help)");
        return ExitCode::Usage;
    }
    return std::nullopt;
}

ExitCode CliApp::runChosen() {
    for (const auto& command : commands_)
        if (command->chosen())
            return command->run();
    // require_subcommand(1) makes this unreachable; say so rather than exit 0 silently.
    printError("no command given (see airtrap-cli --help)");
    return ExitCode::Usage;
}

int CliApp::run(int argc, char** argv) {
    // Past a file-size limit (ulimit -f) the kernel's default is to kill the process, leaving
    // temporary files and a manifest that still says "baking"; ignored, the write fails with
    // EFBIG and is reported and cleaned up like a full disk.
    std::signal(SIGXFSZ, SIG_IGN);
    if (const std::optional<ExitCode> done = parse(argc, argv))
        return static_cast<int>(*done);
    try {
        return static_cast<int>(runChosen());
    } catch (const Error& error) {
        printError(error.what());
        return static_cast<int>(exitCodeFor(error.kind()));
    } catch (const SchedulerError& error) {
        printError(error.what());
        return static_cast<int>(ExitCode::Scheduler);
    } catch (const std::exception& error) {
        printError(std::string("internal error: ") + error.what());
        return static_cast<int>(ExitCode::Internal);
    }
}

} // namespace airtrap::cli
