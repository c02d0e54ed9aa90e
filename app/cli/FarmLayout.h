#pragma once
// Where a farm submission keeps its files (docs/FARM.md "The output folder"): DIR/wedges.json,
// one folder per wedge (its cache, post results and DIR/<wedge>/export), and DIR/farm with the
// job scripts, submit.sh, the jobs' logs and the exit records the scripts leave.
#include <filesystem>
#include <string>

namespace airtrap::cli {

struct FarmLayout {
    std::filesystem::path root;
    //! A dry run writes its scripts, submit.sh and listing in DIR/farm/dry-run, apart from what
    //! a submission in DIR runs and reads.
    bool dryRun = false;

    std::filesystem::path wedgesFile() const { return root / "wedges.json"; }
    std::filesystem::path farmDir() const { return root / "farm"; }
    std::filesystem::path scriptsDir() const { return dryRun ? farmDir() / "dry-run" : farmDir(); }
    std::filesystem::path jobsDir() const { return scriptsDir() / "jobs"; }
    //! Where this run's listing goes: wedges.json, or the dry run's own.
    std::filesystem::path listingFile() const {
        return dryRun ? scriptsDir() / "wedges.json" : wedgesFile();
    }
    std::filesystem::path logsDir() const { return farmDir() / "logs"; }
    std::filesystem::path recordsDir() const { return farmDir() / "records"; }
    std::filesystem::path submitScript() const { return scriptsDir() / "submit.sh"; }
    std::filesystem::path wedgeDir(const std::string& wedge) const { return root / wedge; }
    std::filesystem::path contactSheet() const { return root / "contact_sheet.png"; }
    std::filesystem::path sheetTiles() const { return scriptsDir() / "contact_sheet.tsv"; }
    std::filesystem::path sheetRender(const std::string& wedge) const {
        return farmDir() / "sheet" / (wedge + ".png");
    }
    std::filesystem::path exportDir(const std::string& wedge) const {
        return wedgeDir(wedge) / "export";
    }
    //! The record a job's script writes when it ends; `task` < 0 for a single job.
    std::filesystem::path record(const std::string& jobKey, int task) const {
        return recordsDir() / (jobKey + (task >= 0 ? "-" + std::to_string(task) : "") + ".txt");
    }
    //! The log of a job: %j is the job id, %A_%a the array's id and the task's index.
    std::filesystem::path logPattern(const std::string& jobKey, bool array) const {
        return logsDir() / (jobKey + (array ? "-%A_%a.log" : "-%j.log"));
    }
};

} // namespace airtrap::cli
