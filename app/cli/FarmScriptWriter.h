#pragma once
// The job scripts of a farm submission (docs/FARM.md "Job scripts"): plain bash an artist or a
// wrangler can read and run by hand (`bash DIR/farm/jobs/bake-0.sh`; an array's task as
// `bash post-0.sh TASK`). Each runs airtrap-cli in the background and passes the scheduler's
// warning signal on and writes an exit record when it ends; a bake's — the one scheduler-specific
// function — asks Slurm to requeue the job when the bake stopped for that warning. Every value from
// the scene, a wedge or the command line is written as one single-quoted shell word, so none is
// ever run by the shell.
#include "FarmJob.h"
#include "FarmLayout.h"
#include "FarmListing.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class FarmScriptWriter {
public:
    explicit FarmScriptWriter(FarmLayout layout) : layout_(std::move(layout)) {}

    //! The script of `job`: it runs each of `commands` (argument lists, where kFrames and
    //! kPart stand for the array task's frame chunk and part name) in turn until one fails.
    //! `description` heads it. With `requeueCache` (a bake's cache folder), an exit 75 requeues
    //! the job if the run added a frame to that cache.
    std::string script(const FarmJob& job, const std::string& description,
                       const std::vector<std::vector<std::string>>& commands,
                       const std::string& requeueCache = {}) const;

    //! One render of a contact sheet: a wedge's cache and the picture of it.
    struct SheetRender {
        std::string cache;
        std::string picture;
    };
    //! What the contact sheet shows and where it goes.
    struct ContactSheetPlan {
        std::string editor; //!< the editor's path on the nodes
        int frame = 1;
        int columns = 1;   //!< tiles per row
        std::string tiles; //!< the list of pictures and labels (ContactSheet::readTiles)
        std::string sheet; //!< the PNG
    };
    //! The contact sheet's script: the editor renders the frame of each cache through Xvfb
    //! where the node has no display, then tiles the pictures. A wedge without the frame leaves
    //! a grey tile; the sheet is made regardless.
    std::string contactSheetScript(const FarmJob& job, const ContactSheetPlan& plan,
                                   const std::vector<SheetRender>& renders) const;

    //! farm/submit.sh: the sbatch command of every job in order, chained through shell variables
    //! holding the ids, with `extraOptions` (the user's --sbatch) on each.
    std::string submitScript(const FarmListing& listing,
                             const std::vector<std::string>& extraOptions) const;

    //! Writes `text` to `path` atomically, executable.
    static void write(const std::string& path, const std::string& text);

    //! The placeholder for the array task's frames in a command's arguments.
    static constexpr const char* kFrames = "{frames}";
    //! The placeholder for a part name unique to the array task ("chunk-N", post --part).
    static constexpr const char* kPart = "{part}";

private:
    std::string header(const FarmJob& job, const std::string& description) const;
    std::string chunkSelection(const FarmJob& job) const;
    //! Header, chunk, record and the runner functions: all a script has before its commands.
    std::string opening(const FarmJob& job, const std::string& description,
                        const std::string& requeueCache) const;
    std::string submitLine(const FarmJob& job, const std::vector<std::string>& extraOptions) const;
    static std::string commandLine(const std::vector<std::string>& arguments);

    FarmLayout layout_;
};

} // namespace airtrap::cli
