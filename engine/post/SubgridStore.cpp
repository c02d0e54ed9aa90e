#include "post/SubgridStore.h"

#include "cache/FrameFile.h"
#include "core/Error.h"
#include "io/SequenceName.h"
#include "post/FrameEntries.h"
#include "post/ManifestJson.h"
#include "post/PostStore.h"
#include "post/SubgridFile.h"

#include <filesystem>

namespace airtrap {

namespace {

constexpr const char* kFormatName = "airtrap-subgrid";

std::string fileName(int frame) {
    return sequenceFileName("subgrid", frame, "atb");
}

nlohmann::json entryToJson(const SubgridFrameEntry& entry) {
    return {{"frame", entry.frame},
            {"chain_crc32", entry.chainCrc32},
            {"file", fileName(entry.frame)},
            {"bubbles", entry.bubbles}};
}

SubgridFrameEntry entryFromJson(const nlohmann::json& json, const std::string& path) {
    try {
        SubgridFrameEntry entry;
        entry.frame = json.at("frame").get<int>();
        entry.chainCrc32 = json.at("chain_crc32").get<std::uint32_t>();
        entry.bubbles = json.at("bubbles").get<std::uint32_t>();
        if (entry.frame < 1)
            throw Error(ErrorKind::CacheCorrupt, path + ": frame " + std::to_string(entry.frame));
        return entry;
    } catch (const nlohmann::json::exception& error) {
        throw Error(ErrorKind::CacheCorrupt, path + ": a frame entry: " + error.what());
    }
}

} // namespace

SubgridStore::SubgridStore(std::string dir, nlohmann::json settings,
                           std::vector<SubgridFrameEntry> frames)
    : dir_(std::move(dir)), settings_(std::move(settings)), frames_(std::move(frames)) {}

SubgridStore SubgridStore::open(const std::string& cacheDir) {
    const std::string dir = (std::filesystem::path(cacheDir) / PostStore::kFolderName).string();
    const std::string path = dir + "/" + kManifestName;
    const std::optional<nlohmann::json> json = readManifestJson(path, kFormatName, kFormatVersion);
    if (!json)
        return SubgridStore(dir, nlohmann::json::object(), {});
    std::vector<SubgridFrameEntry> frames;
    for (const nlohmann::json& entry : json->value("frames", nlohmann::json::array()))
        frames.push_back(entryFromJson(entry, path));
    sortByFrame(frames);
    return SubgridStore(dir, json->value("settings", nlohmann::json::object()), std::move(frames));
}

std::uint32_t SubgridStore::chainCrc32(std::uint32_t previousChain, std::uint32_t frameCrc32) {
    const std::uint32_t both[2] = {previousChain, frameCrc32};
    return computeCrc32(both, sizeof both);
}

std::string SubgridStore::manifestPath() const {
    return dir_ + "/" + kManifestName;
}

void SubgridStore::useSettings(const nlohmann::json& settings) {
    if (settings == settings_)
        return;
    settings_ = settings;
    frames_.clear();
    if (std::filesystem::exists(manifestPath()))
        writeManifest();
}

const SubgridFrameEntry* SubgridStore::entry(int frame) const {
    return findFrame(frames_, frame);
}

bool SubgridStore::isCurrent(int frame, std::uint32_t chainCrc32) const {
    const SubgridFrameEntry* listed = entry(frame);
    return listed != nullptr && listed->chainCrc32 == chainCrc32;
}

bool SubgridStore::isCurrentIn(const CacheManifest& manifest, int frame) const {
    std::uint32_t chain = 0;
    for (const CacheFrameEntry& entry : manifest.frames) {
        chain = chainCrc32(chain, entry.crc32);
        if (entry.frame == frame)
            return isCurrent(frame, chain);
    }
    return false;
}

bool SubgridStore::hasFrame(int frame) const {
    return entry(frame) != nullptr;
}

std::vector<int> SubgridStore::frames() const {
    std::vector<int> listed;
    for (const SubgridFrameEntry& entry : frames_)
        listed.push_back(entry.frame);
    return listed;
}

void SubgridStore::writeFrame(const SubgridFrameEntry& entry, const SubgridFrame& bubbles) {
    createResultFolder(dir_);
    SubgridFile::write(dir_ + "/" + fileName(entry.frame), bubbles);
    putFrame(frames_, entry);
    writeManifest();
}

SubgridFrame SubgridStore::readFrame(int frame) const {
    if (!hasFrame(frame))
        throw Error(ErrorKind::InvalidInput, "frame " + std::to_string(frame) +
                                                 " has no sub-grid bubbles in " + dir_ +
                                                 "; run `airtrap-cli post` on the cache first");
    return SubgridFile::read(dir_ + "/" + fileName(frame));
}

void SubgridStore::writeManifest() const {
    nlohmann::json frames = nlohmann::json::array();
    for (const SubgridFrameEntry& entry : frames_)
        frames.push_back(entryToJson(entry));
    writeManifestJson(manifestPath(), kFormatName, kFormatVersion, settings_, frames);
}

} // namespace airtrap
