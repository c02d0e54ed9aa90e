#pragma once
// `airtrap-cli farm submit SCENE --out DIR [--wedge key=VALUE ...] [--wedge-file F.json]
// [--stages bake,post,export] [--export obj,vdb,ply] [--chunk N] [--frames A:B] [--threads N]
// [--sbatch key=value ...] [--signal SIG] [--contact-sheet FRAME [--editor PATH]] [--dry-run]
// [--overwrite]`: validates every wedge,
// writes the job scripts under DIR/farm, submits them chained by afterok and records them in
// DIR/wedges.json (docs/FARM.md).
#include "Command.h"
#include "FarmLayout.h"
#include "FarmListing.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class FarmSubmitCommand : public Command {
public:
    void addTo(CLI::App& parent) override;
    ExitCode run() override;

private:
    //! Refuses bad stages, formats and --sbatch options before anything else.
    void checkOptions() const;
    //! Every wedge, each loaded as its bake will load it: a wedge that does not validate stops
    //! the submission, named with its values.
    FarmListing planWedges() const;
    //! Refuses an output folder that holds other bakes (unless --overwrite, which clears them;
    //! a dry run deletes nothing).
    void prepareFolder(const FarmListing& listing, const FarmLayout& layout) const;
    void createFolders(const FarmLayout& layout) const;
    //! The jobs of one wedge, with their scripts written.
    std::vector<FarmJob> planJobs(const FarmWedge& entry, std::size_t index,
                                  const FarmLayout& layout) const;
    FarmJob bakeJob(const FarmWedge& entry, const std::string& suffix,
                    const FarmLayout& layout) const;
    std::vector<FarmJob> postJobs(const FarmWedge& entry, const std::string& suffix,
                                  const std::vector<std::string>& after,
                                  const FarmLayout& layout) const;
    std::vector<FarmJob> exportJobs(const FarmWedge& entry, const std::string& suffix,
                                    const std::vector<std::string>& after,
                                    const FarmLayout& layout) const;
    //! Refuses a --contact-sheet frame that some wedge does not bake.
    void checkContactSheetFrame(const FarmListing& listing) const;
    //! Refuses to touch a folder whose earlier submission still has jobs queued or running.
    void refuseWhileRunning(const FarmListing& earlier, const FarmLayout& layout) const;
    //! The editor that renders the contact sheet: --editor, or `airtrap` beside airtrap-cli.
    std::string editorPath() const;
    //! Submits in order, each with afterok on the ids of the jobs it waits for. When one is
    //! refused, cancels those already queued and throws.
    void submitAll(FarmListing& listing, const FarmLayout& layout) const;
    void report(const FarmListing& listing, const FarmLayout& layout) const;

    std::vector<std::string> resourceOptions() const;
    std::vector<std::string> extraOptions() const;
    std::vector<std::string> chunks(const FarmWedge& entry) const;
    bool hasStage(const std::string& stage) const;

    std::string scenePath_;
    std::string outDir_;
    std::vector<std::string> wedges_;
    std::string wedgeFile_;
    std::vector<std::string> overrides_;
    std::vector<std::string> stages_ = {"bake", "post", "export"};
    std::vector<std::string> formats_ = {"obj"};
    std::string up_ = "y";
    int chunk_ = 10;
    std::string framesText_;
    int threads_ = 0;
    std::vector<std::string> sbatch_;
    std::string signal_ = "B:USR1@120";
    bool dryRun_ = false;
    bool overwrite_ = false;
    int contactSheetFrame_ = 0;
    std::string editor_;
};

} // namespace airtrap::cli
