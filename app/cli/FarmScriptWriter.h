#pragma once
// The job scripts of a farm submission (docs/FARM.md "Job scripts"): plain bash an artist or a
// wrangler can read and run by hand (`bash DIR/farm/jobs/bake-0.sh`; an array's task as
// `bash post-0.sh TASK`). Each runs airtrap-cli in the background and passes the scheduler's
// warning signal on, writes an exit record when it ends, and — the one scheduler-specific line —
// asks Slurm to requeue the job when the bake stopped for that warning. Every value from the
// scene, a wedge or the command line is written as one single-quoted shell word, so none is
// ever run by the shell.
#include "FarmJob.h"
#include "FarmLayout.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class FarmScriptWriter {
public:
    explicit FarmScriptWriter(FarmLayout layout) : layout_(std::move(layout)) {}

    //! The script of `job`: it runs each of `commands` (argument lists, where kFrames and
    //! kPart stand for the array task's frame chunk and part name) in turn until one fails.
    //! `description` heads it.
    std::string script(const FarmJob& job, const std::string& description,
                       const std::vector<std::vector<std::string>>& commands) const;

    //! One render of a contact sheet: a wedge's cache and the picture of it.
    struct SheetRender {
        std::string cache;
        std::string picture;
    };
    //! The contact sheet's script: the editor (`editor`) renders `frame` of each cache through
    //! Xvfb where the node has no display, then tiles the pictures listed in `tiles` into
    //! `sheet`. A wedge without the frame leaves a grey tile; the sheet is made regardless.
    std::string contactSheetScript(const FarmJob& job, const std::string& editor, int frame,
                                   const std::vector<SheetRender>& renders,
                                   const std::string& tiles, const std::string& sheet) const;

    //! Writes `text` to `path` atomically, executable.
    static void write(const std::string& path, const std::string& text);

    //! The placeholder for the array task's frames in a command's arguments.
    static constexpr const char* kFrames = "{frames}";
    //! The placeholder for a part name unique to the array task ("chunk-N", post --part).
    static constexpr const char* kPart = "{part}";

private:
    std::string header(const FarmJob& job, const std::string& description) const;
    std::string chunkSelection(const FarmJob& job) const;
    static std::string commandLine(const std::vector<std::string>& arguments);

    FarmLayout layout_;
};

} // namespace airtrap::cli
