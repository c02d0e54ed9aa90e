#include "FarmScriptWriter.h"

#include "ShellQuote.h"
#include "SlurmScheduler.h"
#include "core/AtomicFile.h"
#include "core/Error.h"

#include <algorithm>
#include <filesystem>

namespace airtrap::cli {

namespace {

// Every script: how airtrap-cli runs, and the record the script leaves when it ends.
constexpr const char* kRunner = R"SH(
# airtrap-cli runs in the background so that a signal sent to this shell reaches it at once: a
# shell runs its traps only after a foreground child ends. SIGUSR1 (the warning before a time
# limit or a preemption) is passed on, also one that came before the child started; a cancel's
# SIGTERM reaches every process of the job by itself, so the shell only waits to write its
# record.
child=
usr1_pending=
trap 'if [ -n "$child" ]; then kill -USR1 "$child" 2>/dev/null; else usr1_pending=1; fi' USR1
trap ':' TERM INT
run() {
    "$@" &
    child=$!
    if [ -n "$usr1_pending" ]; then
        kill -USR1 "$child" 2>/dev/null
    fi
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
        child=
        return "$status"
    done
}

# The exit record `airtrap-cli farm status` reads where the cluster keeps no accounting.
write_record() {
    printf 'exit=%s\njob=%s\narray_job=%s\ntask=%s\nhost=%s\nstarted=%s\nended=%s\n' "$1" \
        "${SLURM_JOB_ID:-}" "${SLURM_ARRAY_JOB_ID:-}" "${SLURM_ARRAY_TASK_ID:-}" \
        "$(hostname -s)" "$started" "$(date +%s.%N)" >"$record.tmp" &&
        mv -f "$record.tmp" "$record"
}
)SH";

// A job that is not requeued ends with its record.
constexpr const char* kFinish = R"SH(
finish() {
    write_record "$1"
    exit "$1"
}
)SH";

// A bake: exit 75 puts the job back in the queue, to continue from its last good frame.
constexpr const char* kRequeueingFinish = R"SH(
frames_in_cache() {
    find "$cache" -maxdepth 1 -name 'frame_*.atf' 2>/dev/null | wc -l
}
frames_at_start=$(frames_in_cache)

# The scheduler's part (Slurm): exit 75 means airtrap-cli stopped for the warning a job gets
# before its time limit or a preemption (SIGUSR1, docs/CLI.md), with its cache consistent. The
# job goes back in the queue and runs this script again, which continues from the last good
# frame. For another scheduler, change this function.
requeue_self() {
    if [ -n "${SLURM_JOB_ID:-}" ]; then
        scontrol requeue "$SLURM_JOB_ID" ||
            echo "airtrap farm: scontrol requeue failed; submit again to continue the bake"
    fi
}

finish() {
    write_record "$1"
    if [ "$1" -eq 75 ]; then
        # A run that made no frame would make none the next time either: the time left after
        # the wait in the queue is shorter than one frame.
        if [ "$(frames_in_cache)" -gt "$frames_at_start" ]; then
            requeue_self
        else
            echo "airtrap farm: no frame made in this run, so not requeued; give the job more" \
                "time (--sbatch time=...)"
        fi
    fi
    exit "$1"
}
)SH";

//! `text` for a `#` comment line: a line break or other control character would end the
//! comment and start a command.
std::string commentSafe(std::string text) {
    std::replace_if(
        text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }, '?');
    return text;
}

} // namespace

std::string FarmScriptWriter::header(const FarmJob& job, const std::string& description) const {
    std::string text =
        "#!/bin/bash\n# Airtrap farm job " + job.key + ": " + commentSafe(description) + "\n";
    text += "# Written by `airtrap-cli farm submit` (docs/FARM.md); submitted as submit.sh beside "
            "jobs/ shows.\n";
    text += "# By hand: bash " + commentSafe(shellQuote(job.script)) +
            (job.isArray() ? " TASK  (TASK from 0 picks the frame chunk)\n" : "\n");
    std::error_code error;
    const std::filesystem::path self = std::filesystem::canonical("/proc/self/exe", error);
    text += "set -u\n\nairtrap=" + shellQuote(error ? "airtrap-cli" : self.string()) + "\n";
    return text;
}

std::string FarmScriptWriter::chunkSelection(const FarmJob& job) const {
    if (!job.isArray())
        return "record=" + shellQuote(layout_.record(job.key, -1).string()) + "\n";
    std::string text = "\n# The frames of each array task.\nchunks=(";
    for (std::size_t i = 0; i < job.frameChunks.size(); ++i)
        text += (i == 0 ? "" : " ") + shellQuote(job.frameChunks[i]);
    text += ")\ntask=${SLURM_ARRAY_TASK_ID:-${1:-0}}\n";
    // Checked before bash reads it as an index, where it would be evaluated as arithmetic.
    text += "case \"$task\" in\n''|*[!0-9]*) echo \"task must be a number from 0: $task\" >&2; "
            "exit 2 ;;\nesac\n";
    text += "if [ \"$task\" -ge " + std::to_string(job.frameChunks.size()) +
            " ]; then\n    echo \"task must be below " + std::to_string(job.frameChunks.size()) +
            ": $task\" >&2\n    exit 2\nfi\nframes=${chunks[$task]}\n";
    // Task N's record is the job's with "-N" (FarmLayout::record).
    text += "record=" + shellQuote((layout_.recordsDir() / job.key).string()) + "-\"$task\".txt\n";
    return text;
}

std::string FarmScriptWriter::opening(const FarmJob& job, const std::string& description,
                                      const std::string& requeueCache) const {
    std::string text = header(job, description) + chunkSelection(job);
    // A record from an earlier run of this job would read as this run's end.
    text += "rm -f \"$record\"\nstarted=$(date +%s.%N)\n";
    if (!requeueCache.empty())
        text += "cache=" + shellQuote(requeueCache) + "\n";
    return text + kRunner + (requeueCache.empty() ? kFinish : kRequeueingFinish) + "\n";
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
                                     const std::vector<std::vector<std::string>>& commands,
                                     const std::string& requeueCache) const {
    std::string text = opening(job, description, requeueCache);
    for (std::size_t i = 0; i < commands.size(); ++i) {
        text += commandLine(commands[i]) + "\n";
        text += i + 1 < commands.size() ? "status=$?\n[ \"$status\" -eq 0 ] || finish \"$status\"\n"
                                        : "finish \"$?\"\n";
    }
    return text;
}

std::string FarmScriptWriter::contactSheetScript(const FarmJob& job, const ContactSheetPlan& plan,
                                                 const std::vector<SheetRender>& renders) const {
    const std::string frame = std::to_string(plan.frame);
    std::string text = opening(job, "contact sheet of frame " + frame + " of every wedge", "");
    text += "editor=" + shellQuote(plan.editor) + "\n";
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
    // A picture left by an earlier sheet must not stand in for a render that fails now.
    for (const SheetRender& render : renders)
        text += "rm -f " + shellQuote(render.picture) + "\nrender --cache " +
                shellQuote(render.cache) + " --frame " + frame + " --size 640x360 --screenshot " +
                shellQuote(render.picture) + " || echo \"no render of frame " + frame +
                " there; its tile says so\"\n";
    text += "QT_QPA_PLATFORM=offscreen \"$editor\" --contact-sheet " + shellQuote(plan.sheet) +
            " --tiles " + shellQuote(plan.tiles) + " --columns " + std::to_string(plan.columns) +
            " --size 640x360\nfinish \"$?\"\n";
    return text;
}

std::string FarmScriptWriter::submitScript(const FarmListing& listing,
                                           const std::vector<std::string>& extraOptions) const {
    std::string text = "#!/bin/bash\n# The sbatch commands of this farm submission, in order "
                       "(docs/FARM.md): every Slurm option\n# is here. Run it by hand to submit "
                       "the same jobs again (wedges.json keeps the first ids).\nset -eu\n";
    for (const FarmWedge& entry : listing.wedges) {
        text += "\n# wedge " + entry.wedge.name + "\n";
        for (const FarmJob& job : entry.jobs)
            text += submitLine(job, extraOptions);
    }
    if (!listing.finalJobs.empty())
        text += "\n# after every wedge\n";
    for (const FarmJob& job : listing.finalJobs)
        text += submitLine(job, extraOptions);
    return text;
}

std::string FarmScriptWriter::submitLine(const FarmJob& job,
                                         const std::vector<std::string>& extraOptions) const {
    // A job's id lands in a shell variable named after its key ('-' is not allowed there).
    const auto variable = [](std::string key) {
        std::replace(key.begin(), key.end(), '-', '_');
        return "id_" + key;
    };
    std::string line = variable(job.key) + "=$(";
    const std::vector<std::string> arguments = SlurmScheduler::submitArguments(
        job, layout_.logPattern(job.key, job.isArray()).string(), {}, extraOptions);
    for (const std::string& argument : arguments) {
        if (&argument != &arguments.front())
            line += ' ';
        line += shellQuote(argument);
        if (argument == "--parsable" && !job.after.empty()) {
            line += job.afterAny ? " --dependency=afterany" : " --dependency=afterok";
            for (const std::string& key : job.after)
                line += ":\"$" + variable(key) + "\"";
            line += " --kill-on-invalid-dep=yes";
        }
    }
    return line + ")\necho \"" + job.key + ": $" + variable(job.key) + "\"\n";
}

void FarmScriptWriter::write(const std::string& path, const std::string& text) {
    AtomicFile::write(path, text);
    std::error_code error;
    std::filesystem::permissions(path,
                                 std::filesystem::perms::owner_exec |
                                     std::filesystem::perms::group_exec |
                                     std::filesystem::perms::others_exec,
                                 std::filesystem::perm_options::add, error);
    if (error)
        throw Error(ErrorKind::Io,
                    AtomicFile::errorMessage("cannot make executable", path, error.value()));
}

} // namespace airtrap::cli
