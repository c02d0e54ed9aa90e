#include "FarmContactSheet.h"

#include "FarmScriptWriter.h"
#include "core/AtomicFile.h"
#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

namespace airtrap::cli {

int FarmContactSheet::columns(const FarmListing& listing) {
    const std::size_t count = listing.wedges.size();
    const std::size_t keys = count == 0 ? 0 : listing.wedges.front().wedge.keys.size();
    if (keys >= 2) {
        std::set<std::string> lastValues;
        for (const FarmWedge& entry : listing.wedges)
            lastValues.insert(entry.wedge.values.back());
        return int(lastValues.size());
    }
    return std::max(1, int(std::ceil(std::sqrt(double(count)))));
}

std::string FarmContactSheet::label(const FarmWedge& entry) {
    std::string text;
    for (std::size_t i = 0; i < entry.wedge.keys.size(); ++i)
        text += (i == 0 ? "" : "   ") + entry.wedge.keys[i] + " = " + entry.wedge.values[i];
    // One line per tile: a tab or a line break in a value would start another field or tile.
    std::replace_if(
        text.begin(), text.end(), [](char c) { return static_cast<unsigned char>(c) < 0x20; }, ' ');
    return text.empty() ? entry.wedge.name : text;
}

FarmJob FarmContactSheet::plan(const FarmListing& listing, const FarmLayout& layout,
                               const std::string& editor, int frame) {
    FarmJob job;
    job.key = "contact-sheet";
    job.stage = "contact-sheet";
    job.script = (layout.jobsDir() / "contact-sheet.sh").string();
    // After every other job, also failed or cancelled ones: a failed wedge gets a grey tile.
    job.afterAny = true;
    job.schedulerOptions = {"--nodes=1", "--ntasks=1", "--cpus-per-task=1"};
    std::vector<FarmScriptWriter::SheetRender> renders;
    std::string tiles;
    for (const FarmWedge& entry : listing.wedges) {
        for (const FarmJob& other : entry.jobs)
            job.after.push_back(other.key);
        const std::string picture = layout.sheetRender(entry.wedge.name).string();
        renders.push_back({entry.folder, picture});
        tiles += picture + "\t" + label(entry) + "\n";
    }
    std::error_code error;
    const std::filesystem::path picturesDir = layout.sheetRender("tile").parent_path();
    if (std::filesystem::create_directories(picturesDir, error); error)
        throw Error(ErrorKind::Io, AtomicFile::errorMessage("cannot create folder",
                                                            picturesDir.string(), error.value()));
    AtomicFile::write(layout.sheetTiles().string(), tiles);
    const FarmScriptWriter::ContactSheetPlan sheet{.editor = editor,
                                                   .frame = frame,
                                                   .columns = columns(listing),
                                                   .tiles = layout.sheetTiles().string(),
                                                   .sheet = layout.contactSheet().string()};
    FarmScriptWriter::write(job.script,
                            FarmScriptWriter(layout).contactSheetScript(job, sheet, renders));
    return job;
}

} // namespace airtrap::cli
