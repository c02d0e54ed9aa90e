#pragma once
// `airtrap-cli validate SCENE [--set key=value ...]`: reads and checks a scene without baking.
#include "Command.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class ValidateCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    std::string scenePath_;
    std::vector<std::string> overrides_;
};

} // namespace airtrap::cli
