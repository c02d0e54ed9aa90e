#pragma once
// `airtrap-cli post DIR [--frames A:B] [--set surface_mesh.key=value ...] [--threads N]
// [--part NAME] [--no-subgrid]`: makes
// the render outputs of a baked cache (water surfaces and volumes, sub-grid bubbles) and keeps
// them beside it (DIR/post, PostStage), ready for `export` and the editor. Re-running only redoes
// frames that were re-baked since, or all of them when the render settings changed; no
// re-simulation ever.
#include "Command.h"

#include <string>
#include <vector>

namespace airtrap {
struct PostReport;
struct SubgridReport;
} // namespace airtrap

namespace airtrap::cli {

class PostCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    ExitCode summarise(const PostReport& report, const std::string& storeDir) const;
    void summariseSubgrid(const SubgridReport& report) const;

    std::string cacheDir_;
    std::string framesText_;
    std::vector<std::string> overrides_;
    int threads_ = 0;
    bool quiet_ = false;
    std::string part_;
    bool noSubgrid_ = false;
};

} // namespace airtrap::cli
