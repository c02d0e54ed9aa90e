#include "post/SubgridStore.h"

#include "cache/FrameFile.h"
#include "core/Error.h"
#include "post/ManifestJson.h"
#include "post/PostStore.h"
#include "post/SequenceName.h"
#include "post/SubgridFile.h"

#include <filesystem>

namespace airtrap {

namespace {

constexpr const char* kSubgridFormatName = "airtrap-subgrid";

std::string fileName(int frame) {
    return sequenceFileName("subgrid", frame, "atb");
}

} // namespace

nlohmann::json SubgridFrameEntry::toJson() const {
    return {{"frame", frame},
            {"chain_crc32", chainCrc32},
            {"file", fileName(frame)},
            {"bubbles", bubbles}};
}

SubgridFrameEntry SubgridFrameEntry::fromJson(const nlohmann::json& json) {
    return {json.at("frame").get<int>(), json.at("chain_crc32").get<std::uint32_t>(),
            json.at("bubbles").get<std::uint32_t>()};
}

SubgridStore::SubgridStore(std::string dir, ResultList<SubgridFrameEntry> results)
    : dir_(std::move(dir)), results_(std::move(results)) {}

SubgridStore SubgridStore::open(const std::string& cacheDir) {
    const std::string dir = (std::filesystem::path(cacheDir) / PostStore::kFolderName).string();
    return SubgridStore(dir, ResultList<SubgridFrameEntry>::open(
                                 dir + "/" + kManifestName, kSubgridFormatName, kFormatVersion));
}

SubgridStore SubgridStore::openOrEmpty(const std::string& cacheDir, std::string& damage) {
    const std::string dir = (std::filesystem::path(cacheDir) / PostStore::kFolderName).string();
    return SubgridStore(dir, ResultList<SubgridFrameEntry>::openOrEmpty(dir + "/" + kManifestName,
                                                                        kSubgridFormatName,
                                                                        kFormatVersion, damage));
}

std::uint32_t SubgridStore::chainCrc32(std::uint32_t previousChain, std::uint32_t frameCrc32) {
    const std::uint32_t both[2] = {previousChain, frameCrc32};
    return computeCrc32(both, sizeof both);
}

void SubgridStore::useSettings(const nlohmann::json& settings) {
    results_.useSettings(settings);
}

const SubgridFrameEntry* SubgridStore::entry(int frame) const {
    return results_.find(frame);
}

bool SubgridStore::isCurrent(int frame, std::uint32_t chainCrc32) const {
    const SubgridFrameEntry* listed = entry(frame);
    return listed != nullptr && listed->chainCrc32 == chainCrc32 && isIntact(frame);
}

bool SubgridStore::isIntact(int frame) const {
    // The list holds no checksum of the file; the file's own (magic, version, CRC-32 trailer)
    // tells whether it is whole. The files are small: reading one costs little.
    try {
        (void)readFrame(frame);
        return true;
    } catch (const Error&) {
        return false;
    }
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
    return results_.frames();
}

void SubgridStore::writeFrame(const SubgridFrameEntry& entry, const SubgridFrame& bubbles) {
    createResultFolder(dir_);
    SubgridFile::write(dir_ + "/" + fileName(entry.frame), bubbles);
    results_.put(entry);
}

SubgridFrame SubgridStore::readFrame(int frame) const {
    if (!hasFrame(frame))
        throw Error(ErrorKind::InvalidInput, "frame " + std::to_string(frame) +
                                                 " has no sub-grid bubbles in " + dir_ +
                                                 "; run `airtrap-cli post` on the cache first");
    const std::string path = dir_ + "/" + fileName(frame);
    if (std::error_code error; !std::filesystem::exists(path, error))
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": missing (listed in " + dir_ + "/" + kManifestName + ")");
    return SubgridFile::read(path);
}

} // namespace airtrap
