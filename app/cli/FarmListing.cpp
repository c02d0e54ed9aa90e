#include "FarmListing.h"

#include "core/AtomicFile.h"
#include "core/Error.h"

namespace airtrap::cli {

namespace {

nlohmann::json jobJson(const FarmJob& job) {
    return {{"key", job.key},
            {"stage", job.stage},
            {"id", job.id},
            {"script", job.script},
            {"after", job.after},
            {"after_any", job.afterAny},
            {"frame_chunks", job.frameChunks}};
}

FarmJob jobFrom(const nlohmann::json& json, const std::string& wedge) {
    FarmJob job;
    job.key = json.at("key").get<std::string>();
    job.stage = json.at("stage").get<std::string>();
    job.id = json.at("id").get<std::string>();
    job.script = json.at("script").get<std::string>();
    job.after = json.at("after").get<std::vector<std::string>>();
    job.frameChunks = json.at("frame_chunks").get<std::vector<std::string>>();
    job.afterAny = json.value("after_any", false);
    job.wedge = wedge;
    return job;
}

nlohmann::json wedgeJson(const FarmWedge& entry) {
    nlohmann::json jobs = nlohmann::json::array();
    for (const FarmJob& job : entry.jobs)
        jobs.push_back(jobJson(job));
    return {{"name", entry.wedge.name},
            {"keys", entry.wedge.keys},
            {"values", entry.wedge.values},
            {"folder", entry.folder},
            {"frame_start", entry.firstFrame},
            {"frame_end", entry.lastFrame},
            {"jobs", jobs}};
}

FarmWedge wedgeFrom(const nlohmann::json& json) {
    FarmWedge entry;
    entry.wedge.name = json.at("name").get<std::string>();
    entry.wedge.keys = json.at("keys").get<std::vector<std::string>>();
    entry.wedge.values = json.at("values").get<std::vector<std::string>>();
    entry.folder = json.at("folder").get<std::string>();
    entry.firstFrame = json.at("frame_start").get<int>();
    entry.lastFrame = json.at("frame_end").get<int>();
    for (const nlohmann::json& job : json.at("jobs"))
        entry.jobs.push_back(jobFrom(job, entry.wedge.name));
    return entry;
}

} // namespace

nlohmann::json FarmListing::toJson() const {
    nlohmann::json list = nlohmann::json::array();
    for (const FarmWedge& entry : wedges)
        list.push_back(wedgeJson(entry));
    nlohmann::json lastJobs = nlohmann::json::array();
    for (const FarmJob& job : finalJobs)
        lastJobs.push_back(jobJson(job));
    return {{"format", kFormatName},  {"version", kVersion}, {"scene", scene},
            {"overrides", overrides}, {"wedges", list},      {"final_jobs", lastJobs}};
}

FarmListing FarmListing::read(const std::string& path) {
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    const nlohmann::json json = nlohmann::json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (json.is_discarded() || !json.is_object() || json.value("format", "") != kFormatName ||
        json.value("version", 0) != kVersion)
        throw Error(ErrorKind::InvalidInput,
                    path + ": not a farm listing of this version (expected \"format\": \"" +
                        kFormatName + "\", \"version\": " + std::to_string(kVersion) + ")");
    FarmListing listing;
    try {
        listing.scene = json.at("scene").get<std::string>();
        listing.overrides = json.at("overrides").get<std::vector<std::string>>();
        for (const nlohmann::json& wedge : json.at("wedges"))
            listing.wedges.push_back(wedgeFrom(wedge));
        for (const nlohmann::json& job : json.value("final_jobs", nlohmann::json::array()))
            listing.finalJobs.push_back(jobFrom(job, ""));
    } catch (const nlohmann::json::exception& error) {
        throw Error(ErrorKind::InvalidInput, path + ": " + error.what());
    }
    return listing;
}

void FarmListing::write(const std::string& path) const {
    AtomicFile::write(path, toJson().dump(2) + "\n");
}

bool FarmListing::sameBakes(const FarmListing& other) const {
    if (scene != other.scene || overrides != other.overrides ||
        wedges.size() != other.wedges.size())
        return false;
    for (std::size_t i = 0; i < wedges.size(); ++i) {
        const FarmWedge& a = wedges[i];
        const FarmWedge& b = other.wedges[i];
        if (a.folder != b.folder || a.wedge.keys != b.wedge.keys ||
            a.wedge.values != b.wedge.values)
            return false;
    }
    return true;
}

std::vector<std::string> FarmListing::jobIds() const {
    std::vector<std::string> ids;
    for (const FarmWedge& entry : wedges)
        for (const FarmJob& job : entry.jobs)
            if (!job.id.empty())
                ids.push_back(job.id);
    for (const FarmJob& job : finalJobs)
        if (!job.id.empty())
            ids.push_back(job.id);
    return ids;
}

} // namespace airtrap::cli
