#include "FarmSubmitCommand.h"

#include "FarmContactSheet.h"
#include "FarmScriptWriter.h"
#include "FrameRange.h"
#include "Joined.h"
#include "SceneLoader.h"
#include "SchedulerError.h"
#include "ShellQuote.h"
#include "SlurmScheduler.h"
#include "cache/FrameCache.h"
#include "core/AtomicFile.h"
#include "core/Error.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <map>
#include <unistd.h>

namespace fs = std::filesystem;

namespace airtrap::cli {

namespace {

const std::vector<std::string> kStages = {"bake", "post", "export"};
const std::vector<std::string> kFormats = {"obj", "vdb", "ply"};

//! `path` made absolute, with "." and ".." and symbolic links resolved where it exists: the job
//! scripts run on other machines, from other working folders.
std::string absolute(const std::string& path) {
    std::error_code error;
    const fs::path whole = fs::absolute(path, error);
    const fs::path resolved = fs::weakly_canonical(whole, error);
    return (error ? whole : resolved).string();
}

//! `key=value` of --sbatch as sbatch's own `--key=value`.
std::string sbatchOption(const std::string& assignment) {
    const std::size_t equals = assignment.find('=');
    const std::string key = assignment.substr(0, equals);
    const bool plain = !key.empty() && std::isalpha(static_cast<unsigned char>(key[0])) &&
                       key.find_first_not_of("abcdefghijklmnopqrstuvwxyz-") == std::string::npos;
    if (!plain)
        throw Error(ErrorKind::InvalidInput,
                    "--sbatch " + assignment +
                        ": expected key=value with an sbatch long option as key, e.g. "
                        "partition=sim or time=02:00:00");
    return equals == std::string::npos ? "--" + key : "--" + assignment;
}

FarmJob newJob(const std::string& key, const std::string& stage, const std::string& wedge) {
    FarmJob job;
    job.key = key;
    job.stage = stage;
    job.wedge = wedge;
    return job;
}

} // namespace

void FarmSubmitCommand::addTo(CLI::App& parent) {
    app_ = parent.add_subcommand("submit", "Submit the bake, post and export of a scene and its "
                                           "wedges as chained Slurm jobs");
    app_->add_option("SCENE", scenePath_, "Scene file (JSON)")->required();
    app_->add_option("--out,-o", outDir_,
                     "Output folder on a file system every node shares: one folder per wedge, "
                     "the job scripts in DIR/farm, DIR/wedges.json")
        ->required();
    app_->add_option("--wedge", wedges_,
                     "key=VALUE in --set's syntax; repeat a key for more values, several keys "
                     "make the cross product")
        ->allow_extra_args(false);
    app_->add_option("--wedge-file", wedgeFile_,
                     "JSON object: each key with the array of its values");
    app_->add_option("--set", overrides_, "Override a scene value in every wedge (repeatable)")
        ->allow_extra_args(false);
    app_->add_option("--stages", stages_, "Stages to run, in order: bake,post,export")
        ->delimiter(',')
        ->allow_extra_args(false);
    app_->add_option("--export", formats_, "Export formats: obj,vdb,ply (default obj)")
        ->delimiter(',')
        ->allow_extra_args(false);
    app_->add_option("--up", up_, "Up axis of the exported files: y (default) or z")
        ->check(CLI::IsMember({"y", "z"}));
    app_->add_option("--chunk", chunk_, "Frames per post and export task (default 10)")
        ->check(CLI::Range(1, 100000));
    app_->add_option("--frames", framesText_, "Frames: A:B (default: the scene's)");
    app_->add_option("--threads,-j", threads_,
                     "Cores per job (0 = a whole node for each job, the default)")
        ->check(CLI::Range(0, 4096));
    app_->add_option("--sbatch", sbatch_,
                     "key=value passed to sbatch as --key=value (partition, account, time, "
                     "mem, …; repeatable)")
        ->allow_extra_args(false);
    app_->add_option("--signal", signal_,
                     "Warning signal before the time limit, sbatch's --signal syntax (default "
                     "B:USR1@120)");
    app_->add_option("--contact-sheet", contactSheetFrame_,
                     "After every wedge, render this frame of each with the editor and tile the "
                     "pictures, labelled by their values, into DIR/contact_sheet.png")
        ->check(CLI::Range(1, 1000000));
    app_->add_option("--editor", editor_,
                     "The editor on the nodes, for --contact-sheet (default: airtrap beside "
                     "airtrap-cli)");
    app_->add_flag("--dry-run", dryRun_,
                   "Write the job scripts and print the sbatch commands; "
                   "submit nothing");
    app_->add_flag("--overwrite", overwrite_,
                   "Replace the bakes of an earlier submission with other values in --out");
}

bool FarmSubmitCommand::hasStage(const std::string& stage) const {
    return std::find(stages_.begin(), stages_.end(), stage) != stages_.end();
}

void FarmSubmitCommand::checkOptions() const {
    for (const std::string& stage : stages_)
        if (std::find(kStages.begin(), kStages.end(), stage) == kStages.end())
            throw Error(ErrorKind::InvalidInput,
                        "--stages " + stage + ": expected bake, post or export");
    for (const std::string& format : formats_)
        if (std::find(kFormats.begin(), kFormats.end(), format) == kFormats.end())
            throw Error(ErrorKind::InvalidInput,
                        "--export " + format + ": expected obj, vdb or ply");
    for (const std::string& option : sbatch_)
        sbatchOption(option);
    // Paths end up in job scripts, one quoted word each, and in their comments, where a line
    // break would end the comment and start a command.
    for (const auto& [option, path] :
         {std::pair{"SCENE", scenePath_}, {"--out", outDir_}, {"--editor", editor_}})
        if (std::any_of(path.begin(), path.end(),
                        [](char c) { return static_cast<unsigned char>(c) < 0x20; }))
            throw Error(ErrorKind::InvalidInput,
                        std::string(option) +
                            ": the path holds a control character (a line break, a tab); "
                            "choose one without");
    if (contactSheetFrame_ > 0)
        editorPath();
    if (signal_.empty() || signal_.find_first_of(" \t\n'\"") != std::string::npos)
        throw Error(ErrorKind::InvalidInput,
                    "--signal " + signal_ + ": expected sbatch's syntax, e.g. B:USR1@120");
}

FarmListing FarmSubmitCommand::planWedges() const {
    WedgePlan plan;
    if (!wedgeFile_.empty())
        plan.addFile(wedgeFile_);
    plan.addAssignments(wedges_);
    FarmListing listing;
    listing.scene = absolute(scenePath_);
    listing.overrides = overrides_;
    const FarmLayout layout{absolute(outDir_)};
    for (const Wedge& wedge : plan.wedges()) {
        std::vector<std::string> assignments = overrides_;
        for (const std::string& assignment : wedge.assignments())
            assignments.push_back(assignment);
        LoadedScene loaded;
        try {
            loaded = SceneLoader::load(scenePath_, assignments);
        } catch (const Error& error) {
            throw Error(error.kind(),
                        "wedge " + wedge.name +
                            (wedge.keys.empty()
                                 ? ""
                                 : " (--wedge " + joined(wedge.assignments(), ", ") + ")") +
                            ": " + error.what());
        }
        const FrameRange range =
            FrameRange::parse(framesText_, loaded.scene.frames.endFrame, "frames.end_frame");
        listing.wedges.push_back(FarmWedge{.wedge = wedge,
                                           .folder = layout.wedgeDir(wedge.name).string(),
                                           .firstFrame = range.first(),
                                           .lastFrame = range.last(),
                                           .jobs = {}});
    }
    return listing;
}

void FarmSubmitCommand::refuseWhileRunning(const FarmListing& earlier,
                                           const FarmLayout& layout) const {
    std::vector<std::string> running;
    for (const auto& [id, state] : SlurmScheduler::queued(earlier.jobIds()))
        if (state.active())
            running.push_back(id);
    if (!running.empty())
        throw Error(ErrorKind::InvalidInput,
                    "jobs of the submission in " + layout.root.string() +
                        " are still queued or running (" + joined(running, ", ") +
                        "); wait for them to end, or run airtrap-cli farm cancel " +
                        shellQuote(layout.root.string()) + " first");
}

void FarmSubmitCommand::prepareFolder(const FarmListing& listing, const FarmLayout& layout) const {
    if (FrameCache::isCache(layout.root.string()))
        throw Error(ErrorKind::InvalidInput,
                    layout.root.string() + " is an Airtrap cache; give farm its own folder");
    std::error_code error;
    if (!fs::exists(layout.wedgesFile(), error))
        return;
    const FarmListing earlier = FarmListing::read(layout.wedgesFile().string());
    // Two bakes into one cache, or a folder deleted under a running job, would lose work.
    if (!dryRun_)
        refuseWhileRunning(earlier, layout);
    if (earlier.sameBakes(listing))
        return; // submitted again: each bake continues its cache (--resume)
    if (!overwrite_)
        throw Error(ErrorKind::InvalidInput,
                    layout.root.string() + " holds the wedges of another submission (" +
                        layout.wedgesFile().string() +
                        "); add --overwrite to replace them, or choose another --out folder");
    if (dryRun_)
        return; // a dry run deletes nothing
    std::vector<fs::path> earlierFiles = {layout.farmDir(), layout.wedgesFile()};
    for (const FarmWedge& entry : earlier.wedges)
        if (fs::path(entry.folder).parent_path() == layout.root)
            earlierFiles.emplace_back(entry.folder);
    for (const fs::path& path : earlierFiles)
        if (fs::remove_all(path, error); error)
            throw Error(ErrorKind::Io,
                        AtomicFile::errorMessage("cannot delete", path.string(), error.value()));
}

std::vector<std::string> FarmSubmitCommand::resourceOptions() const {
    std::vector<std::string> options = {"--nodes=1", "--ntasks=1"};
    options.push_back(threads_ > 0 ? "--cpus-per-task=" + std::to_string(threads_) : "--exclusive");
    return options;
}

std::vector<std::string> FarmSubmitCommand::extraOptions() const {
    std::vector<std::string> options;
    for (const std::string& option : sbatch_)
        options.push_back(sbatchOption(option));
    return options;
}

std::vector<std::string> FarmSubmitCommand::chunks(const FarmWedge& entry) const {
    std::vector<std::string> list;
    for (int first = entry.firstFrame; first <= entry.lastFrame; first += chunk_)
        list.push_back(std::to_string(first) + ":" +
                       std::to_string(std::min(entry.lastFrame, first + chunk_ - 1)));
    return list;
}

FarmJob FarmSubmitCommand::bakeJob(const FarmWedge& entry, const std::string& suffix,
                                   const FarmLayout& layout) const {
    FarmJob job = newJob("bake-" + suffix, "bake", entry.wedge.name);
    job.script = (layout.jobsDir() / (job.key + ".sh")).string();
    job.schedulerOptions = resourceOptions();
    job.schedulerOptions.push_back("--requeue");
    job.schedulerOptions.push_back("--signal=" + signal_);
    // A requeued run writes to the same log: keep what the run before it said.
    job.schedulerOptions.push_back("--open-mode=append");
    std::vector<std::string> bake = {"bake",
                                     absolute(scenePath_),
                                     "--out",
                                     entry.folder,
                                     "--frames",
                                     std::to_string(entry.firstFrame) + ":" +
                                         std::to_string(entry.lastFrame),
                                     "--resume",
                                     "--threads",
                                     std::to_string(threads_)};
    for (const std::string& assignment : overrides_)
        bake.insert(bake.end(), {"--set", assignment});
    for (const std::string& assignment : entry.wedge.assignments())
        bake.insert(bake.end(), {"--set", assignment});
    FarmScriptWriter::write(
        job.script, FarmScriptWriter(layout).script(job, "bake of wedge " + entry.wedge.name,
                                                    {bake}, entry.folder));
    return job;
}

std::vector<FarmJob> FarmSubmitCommand::postJobs(const FarmWedge& entry, const std::string& suffix,
                                                 const std::vector<std::string>& after,
                                                 const FarmLayout& layout) const {
    const FarmScriptWriter writer(layout);
    const std::string threads = std::to_string(threads_);
    FarmJob chunked = newJob("post-" + suffix, "post", entry.wedge.name);
    chunked.script = (layout.jobsDir() / (chunked.key + ".sh")).string();
    chunked.frameChunks = chunks(entry);
    chunked.after = after;
    chunked.schedulerOptions = resourceOptions();
    FarmScriptWriter::write(
        chunked.script, writer.script(chunked,
                                      "water surfaces and volumes of wedge " + entry.wedge.name +
                                          ", one frame chunk per array task",
                                      {{"post", entry.folder, "--frames", FarmScriptWriter::kFrames,
                                        "--part", FarmScriptWriter::kPart, "--threads", threads}}));
    // The sub-grid bubbles go in frame order, so one job does them once every chunk is done;
    // the same run lists the chunks' results in post.json.
    FarmJob merge = newJob("post-merge-" + suffix, "post-merge", entry.wedge.name);
    merge.script = (layout.jobsDir() / (merge.key + ".sh")).string();
    merge.after = {chunked.key};
    merge.schedulerOptions = resourceOptions();
    const std::string range =
        std::to_string(entry.firstFrame) + ":" + std::to_string(entry.lastFrame);
    FarmScriptWriter::write(
        merge.script,
        writer.script(merge,
                      "post.json and the sub-grid bubbles of wedge " + entry.wedge.name +
                          " after its chunks",
                      {{"post", entry.folder, "--frames", range, "--threads", threads}}));
    return {chunked, merge};
}

std::vector<FarmJob> FarmSubmitCommand::exportJobs(const FarmWedge& entry,
                                                   const std::string& suffix,
                                                   const std::vector<std::string>& after,
                                                   const FarmLayout& layout) const {
    const FarmScriptWriter writer(layout);
    const std::string out = layout.exportDir(entry.wedge.name).string();
    const std::string range =
        std::to_string(entry.firstFrame) + ":" + std::to_string(entry.lastFrame);
    FarmJob chunked = newJob("export-" + suffix, "export", entry.wedge.name);
    chunked.script = (layout.jobsDir() / (chunked.key + ".sh")).string();
    chunked.frameChunks = chunks(entry);
    chunked.after = after;
    chunked.schedulerOptions = resourceOptions();
    FarmJob listing = newJob("export-listing-" + suffix, "export-listing", entry.wedge.name);
    listing.script = (layout.jobsDir() / (listing.key + ".sh")).string();
    listing.after = {chunked.key};
    listing.schedulerOptions = {"--nodes=1", "--ntasks=1", "--cpus-per-task=1"};
    std::vector<std::vector<std::string>> writes;
    std::vector<std::vector<std::string>> lists;
    for (const std::string& format : formats_) {
        writes.push_back({"export", entry.folder, "--format", format, "--out", out, "--up", up_,
                          "--frames", FarmScriptWriter::kFrames, "--no-listing", "--quiet"});
        lists.push_back({"export", entry.folder, "--format", format, "--out", out, "--up", up_,
                         "--frames", range, "--listing-only"});
    }
    FarmScriptWriter::write(chunked.script,
                            writer.script(chunked,
                                          joined(formats_, ", ") + " export of wedge " +
                                              entry.wedge.name + ", one frame chunk per task",
                                          writes));
    // export.json lists every chunk's files: written once, by one job after them all.
    FarmScriptWriter::write(
        listing.script, writer.script(listing, "export.json of wedge " + entry.wedge.name, lists));
    return {chunked, listing};
}

std::vector<FarmJob> FarmSubmitCommand::planJobs(const FarmWedge& entry, std::size_t index,
                                                 const FarmLayout& layout) const {
    const std::string suffix = std::to_string(index);
    std::vector<FarmJob> jobs;
    if (hasStage("bake"))
        jobs.push_back(bakeJob(entry, suffix, layout));
    if (hasStage("post")) {
        const std::vector<std::string> after =
            jobs.empty() ? std::vector<std::string>{} : std::vector{jobs.back().key};
        for (FarmJob& job : postJobs(entry, suffix, after, layout))
            jobs.push_back(std::move(job));
    }
    if (hasStage("export")) {
        const std::vector<std::string> after =
            jobs.empty() ? std::vector<std::string>{} : std::vector{jobs.back().key};
        for (FarmJob& job : exportJobs(entry, suffix, after, layout))
            jobs.push_back(std::move(job));
    }
    return jobs;
}

void FarmSubmitCommand::submitAll(FarmListing& listing, const FarmLayout& layout) const {
    std::map<std::string, std::string> ids;
    std::vector<std::string> submitted;
    try {
        const auto submit = [&](FarmJob& job) {
            std::vector<std::string> dependencies;
            for (const std::string& key : job.after)
                dependencies.push_back(ids.at(key));
            job.id = SlurmScheduler::submit(SlurmScheduler::submitArguments(
                job, layout.logPattern(job.key, job.isArray()).string(), dependencies,
                extraOptions()));
            ids[job.key] = job.id;
            submitted.push_back(job.id);
        };
        for (FarmWedge& entry : listing.wedges)
            for (FarmJob& job : entry.jobs)
                submit(job);
        for (FarmJob& job : listing.finalJobs)
            submit(job);
    } catch (const SchedulerError& error) {
        // Nothing half-submitted: a chain missing a link would wait for ever, or run too soon.
        try {
            SlurmScheduler::cancel(submitted);
        } catch (const SchedulerError&) {
        }
        throw SchedulerError(std::string(error.what()) +
                             (submitted.empty()
                                  ? "; nothing was submitted"
                                  : "; cancelled the " + std::to_string(submitted.size()) +
                                        " job(s) already queued"));
    }
}

void FarmSubmitCommand::report(const FarmListing& listing, const FarmLayout& layout) const {
    for (const FarmWedge& entry : listing.wedges) {
        std::cout << "wedge " << entry.wedge.name << " → " << entry.folder << '\n';
        for (const FarmJob& job : entry.jobs) {
            std::cout << "  " << job.stage << ' ' << (dryRun_ ? "(not submitted)" : job.id);
            if (job.isArray())
                std::cout << " (" << job.frameChunks.size() << " tasks)";
            std::cout << '\n';
        }
    }
    for (const FarmJob& job : listing.finalJobs)
        std::cout << job.stage << ' ' << (dryRun_ ? "(not submitted)" : job.id) << " → "
                  << layout.contactSheet().string() << '\n';
    if (dryRun_)
        std::cout << "dry run: the sbatch commands are in " << layout.submitScript().string()
                  << '\n';
    else
        std::cout << "follow with: airtrap-cli farm status " << shellQuote(layout.root.string())
                  << '\n';
}

void FarmSubmitCommand::createFolders(const FarmLayout& layout) const {
    std::error_code error;
    std::vector<fs::path> folders = {layout.jobsDir()};
    if (!dryRun_) {
        // Records of an earlier submission would read as this one's.
        fs::remove_all(layout.recordsDir(), error);
        folders.insert(folders.end(), {layout.logsDir(), layout.recordsDir()});
    }
    for (const fs::path& dir : folders)
        if (fs::create_directories(dir, error); error)
            throw Error(ErrorKind::Io, AtomicFile::errorMessage("cannot create folder",
                                                                dir.string(), error.value()));
}

std::string FarmSubmitCommand::editorPath() const {
    std::error_code error;
    const fs::path editor = editor_.empty()
                                ? fs::canonical("/proc/self/exe", error).parent_path() / "airtrap"
                                : fs::path(editor_);
    if (!fs::is_regular_file(editor, error) || ::access(editor.c_str(), X_OK) != 0)
        throw Error(ErrorKind::InvalidInput,
                    "--contact-sheet renders with the editor, but " + editor.string() +
                        " is not an executable file; give its path on the nodes with --editor");
    return absolute(editor.string());
}

void FarmSubmitCommand::checkContactSheetFrame(const FarmListing& listing) const {
    for (const FarmWedge& entry : listing.wedges)
        if (contactSheetFrame_ < entry.firstFrame || contactSheetFrame_ > entry.lastFrame)
            throw Error(ErrorKind::InvalidInput,
                        "--contact-sheet " + std::to_string(contactSheetFrame_) + ": wedge " +
                            entry.wedge.name + " bakes frames " + std::to_string(entry.firstFrame) +
                            " to " + std::to_string(entry.lastFrame) +
                            "; choose a frame in that range");
}

ExitCode FarmSubmitCommand::run() {
    checkOptions();
    FarmListing listing = planWedges();
    if (contactSheetFrame_ > 0)
        checkContactSheetFrame(listing);
    const FarmLayout layout{absolute(outDir_), dryRun_};
    if (!dryRun_)
        SlurmScheduler::requireCommands();
    prepareFolder(listing, layout);
    createFolders(layout);
    for (std::size_t i = 0; i < listing.wedges.size(); ++i)
        listing.wedges[i].jobs = planJobs(listing.wedges[i], i, layout);
    if (contactSheetFrame_ > 0)
        listing.finalJobs.push_back(
            FarmContactSheet::plan(listing, layout, editorPath(), contactSheetFrame_));
    const std::string commands = FarmScriptWriter(layout).submitScript(listing, extraOptions());
    FarmScriptWriter::write(layout.submitScript().string(), commands);
    if (dryRun_)
        std::cout << commands << '\n';
    else
        submitAll(listing, layout);
    listing.write(layout.listingFile().string());
    report(listing, layout);
    return ExitCode::Success;
}

} // namespace airtrap::cli
