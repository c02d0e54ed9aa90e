#pragma once
// `airtrap-cli post DIR`: the post stage (free-surface mesh, bubble meshes, sub-grid bubbles)
// comes in a later version; until then the verb exists and says so, and writes nothing.
#include "Command.h"
#include "core/Error.h"

#include <string>

namespace airtrap::cli {

class PostCommand : public Command {
public:
    void addTo(CLI::App& parent) override {
        app_ = parent.add_subcommand("post", "Build meshes from a cache (not available yet)");
        app_->add_option("DIR", cacheDir_, "Cache folder")->required();
    }

    ExitCode run() override {
        throw Error(ErrorKind::NotAvailable,
                    "post is not available yet: the water and bubble meshes come in a later "
                    "version (export --format ply writes the particles now)");
    }

private:
    std::string cacheDir_;
};

} // namespace airtrap::cli
