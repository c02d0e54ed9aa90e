#include "FarmScriptWriter.h"

#include "ShellQuote.h"
#include "core/AtomicFile.h"

#include <filesystem>

namespace airtrap::cli {

namespace {

// Shared by every script: how airtrap-cli is run and how the script ends. Kept word for word in
// docs/FARM.md "Job scripts".
constexpr const char* kRunner = R"SH(
# The scheduler's part (Slurm): exit 75 means airtrap-cli stopped for the warning a job gets
# before its time limit or a preemption (SIGUSR1, docs/CLI.md), with its cache consistent. The
# job goes back in the queue and runs this script again, which continues from the last good
# frame. For another scheduler, change this function.
requeue_self() {
    if [ -n "${SLURM_JOB_ID:-}" ]; then
        scontrol requeue "$SLURM_JOB_ID"
    fi
}

# airtrap-cli runs in the background so that a signal sent to this shell reaches it at once: a
# shell runs its traps only after a foreground child ends. SIGUSR1 is passed on; a cancel's
# SIGTERM reaches every process of the job by itself, so the shell only waits to write its
# record.
run() {
    "$@" &
    child=$!
    trap 'kill -USR1 "$child" 2>/dev/null' USR1
    trap ':' TERM INT
    while :; do
        wait "$child"
        status=$?
        # Above 128 with the child alive: a trapped signal interrupted the wait, not its end.
        if [ "$status" -gt 128 ] && kill -0 "$child" 2>/dev/null; then
            continue
        fi
        # The child may have ended as the signal came: bash keeps its status for a second wait.
        if [ "$status" -gt 128 ]; then
            wait "$child"
            status=$?
        fi
        return "$status"
    done
}

# The exit record `airtrap-cli farm status` reads where the cluster keeps no accounting.
finish() {
    printf 'exit=%s\njob=%s\narray_job=%s\ntask=%s\nhost=%s\nstarted=%s\nended=%s\n' "$1" \
        "${SLURM_JOB_ID:-}" "${SLURM_ARRAY_JOB_ID:-}" "${SLURM_ARRAY_TASK_ID:-}" \
        "$(hostname -s)" "$started" "$(date +%s.%N)" >"$record.tmp" &&
        mv -f "$record.tmp" "$record"
    if [ "$1" -eq 75 ]; then
        requeue_self
    fi
    exit "$1"
}
)SH";

} // namespace

std::string FarmScriptWriter::header(const FarmJob& job, const std::string& description) const {
    std::string text = "#!/bin/bash\n# Airtrap farm job " + job.key + ": " + description + "\n";
    text += "# Written by `airtrap-cli farm submit` (docs/FARM.md); submitted as farm/submit.sh "
            "shows.\n";
    text += job.isArray() ? "# By hand: bash " + shellQuote(job.script) +
                                " TASK  (TASK from 0 picks the frame chunk)\n"
                          : "# By hand: bash " + shellQuote(job.script) + "\n";
    text += "set -u\n\n";
    text += "airtrap=" + shellQuote(std::filesystem::canonical("/proc/self/exe").string()) + "\n";
    return text;
}

std::string FarmScriptWriter::chunkSelection(const FarmJob& job) const {
    if (!job.isArray())
        return "record=" + shellQuote(layout_.record(job.key, -1).string()) + "\n";
    std::string text = "\n# The frames of each array task.\nchunks=(";
    for (std::size_t i = 0; i < job.frameChunks.size(); ++i)
        text += (i == 0 ? "" : " ") + shellQuote(job.frameChunks[i]);
    text += ")\ntask=${SLURM_ARRAY_TASK_ID:-${1:-0}}\nframes=${chunks[$task]}\n";
    // Task N's record is the job's with "-N" (FarmLayout::record).
    text += "record=" + shellQuote((layout_.recordsDir() / job.key).string()) + "-\"$task\".txt\n";
    return text;
}

std::string FarmScriptWriter::commandLine(const std::vector<std::string>& arguments) {
    std::string line = "run \"$airtrap\"";
    for (const std::string& argument : arguments)
        line += " " + (argument == kFrames ? std::string("\"$frames\"")
                       : argument == kPart ? std::string("\"chunk-$task\"")
                                           : shellQuote(argument));
    return line;
}

std::string FarmScriptWriter::script(const FarmJob& job, const std::string& description,
                                     const std::vector<std::vector<std::string>>& commands) const {
    std::string text = header(job, description) + chunkSelection(job) + "started=$(date +%s.%N)\n" +
                       kRunner + "\n";
    for (std::size_t i = 0; i < commands.size(); ++i) {
        text += commandLine(commands[i]) + "\n";
        text += i + 1 < commands.size() ? "status=$?\n[ \"$status\" -eq 0 ] || finish \"$status\"\n"
                                        : "finish \"$?\"\n";
    }
    return text;
}

std::string FarmScriptWriter::contactSheetScript(const FarmJob& job, const std::string& editor,
                                                 int frame, const std::vector<SheetRender>& renders,
                                                 const std::string& tiles,
                                                 const std::string& sheet) const {
    std::string text =
        header(job, "contact sheet of frame " + std::to_string(frame) + " of every wedge") +
        chunkSelection(job) + "started=$(date +%s.%N)\n" + kRunner;
    text += "\neditor=" + shellQuote(editor) + "\n";
    text += R"SH(
# The editor draws with OpenGL: on a node without a display, Xvfb gives it one (Mesa renders in
# software there).
render() {
    if [ -n "${DISPLAY:-}" ]; then
        "$editor" "$@"
    else
        xvfb-run -a -s "-screen 0 1280x1024x24" "$editor" "$@"
    fi
}

)SH";
    for (const SheetRender& render : renders)
        text += "render --cache " + shellQuote(render.cache) + " --frame " + std::to_string(frame) +
                " --size 640x360 --screenshot " + shellQuote(render.picture) +
                " || echo \"no render of " + std::to_string(frame) +
                " in that wedge; its tile says so\"\n";
    text += "QT_QPA_PLATFORM=offscreen \"$editor\" --contact-sheet " + shellQuote(sheet) +
            " --tiles " + shellQuote(tiles) + " --size 640x360\nfinish \"$?\"\n";
    return text;
}

void FarmScriptWriter::write(const std::string& path, const std::string& text) {
    AtomicFile::write(path, text);
    std::filesystem::permissions(path,
                                 std::filesystem::perms::owner_exec |
                                     std::filesystem::perms::group_exec |
                                     std::filesystem::perms::others_exec,
                                 std::filesystem::perm_options::add);
}

} // namespace airtrap::cli
