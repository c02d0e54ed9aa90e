#include "post/PostStore.h"

#include "core/Error.h"
#include "post/ManifestJson.h"
#include "post/MeshFile.h"
#include "post/SequenceName.h"
#include "post/WaterVolumeFile.h"

#include <filesystem>

namespace airtrap {

namespace {

constexpr const char* kPostFormatName = "airtrap-post";

std::string meshName(int frame) {
    return sequenceFileName("water", frame, "atm");
}
std::string volumeName(int frame) {
    return sequenceFileName("fluid", frame, "vdb");
}

} // namespace

nlohmann::json PostFrameEntry::toJson() const {
    return {{"frame", frame},           {"source_crc32", sourceCrc32},
            {"water", meshName(frame)}, {"fluid", volumeName(frame)},
            {"triangles", triangles},   {"seconds", seconds}};
}

PostFrameEntry PostFrameEntry::fromJson(const nlohmann::json& json) {
    return {json.at("frame").get<int>(), json.at("source_crc32").get<std::uint32_t>(),
            json.at("triangles").get<std::uint64_t>(), json.at("seconds").get<double>()};
}

PostStore::PostStore(std::string dir, ResultList<PostFrameEntry> results)
    : dir_(std::move(dir)), results_(std::move(results)) {}

PostStore::PostStore(PostStore&& other) noexcept
    : dir_(std::move(other.dir_)), results_(std::move(other.results_)) {}

PostStore PostStore::open(const std::string& cacheDir) {
    const std::string dir = (std::filesystem::path(cacheDir) / kFolderName).string();
    return PostStore(dir, ResultList<PostFrameEntry>::open(dir + "/" + kManifestName,
                                                           kPostFormatName, kFormatVersion));
}

void PostStore::useSettings(const nlohmann::json& settings) {
    const std::lock_guard lock(mutex_);
    results_.useSettings(settings);
}

bool PostStore::isCurrent(int frame, std::uint32_t sourceCrc32) const {
    const std::lock_guard lock(mutex_);
    const PostFrameEntry* entry = results_.find(frame);
    return entry != nullptr && entry->sourceCrc32 == sourceCrc32;
}

bool PostStore::hasFrame(int frame) const {
    const std::lock_guard lock(mutex_);
    return results_.find(frame) != nullptr;
}

std::vector<int> PostStore::frames() const {
    const std::lock_guard lock(mutex_);
    return results_.frames();
}

void PostStore::writeFrame(const PostFrameEntry& entry, const TriangleMesh& freeSurface,
                           const WaterVolume& volume) {
    createResultFolder(dir_);
    MeshFile::write(dir_ + "/" + meshName(entry.frame), freeSurface);
    WaterVolumeFile::write(dir_ + "/" + volumeName(entry.frame), volume, UpAxis::Y);
    const std::lock_guard lock(mutex_);
    results_.put(entry);
}

void PostStore::requireListed(int frame) const {
    if (!hasFrame(frame))
        throw Error(ErrorKind::InvalidInput, "frame " + std::to_string(frame) +
                                                 " has no post results in " + dir_ +
                                                 "; run `airtrap-cli post` on the cache first");
}

TriangleMesh PostStore::readFreeSurface(int frame) const {
    requireListed(frame);
    return MeshFile::read(dir_ + "/" + meshName(frame));
}

WaterVolume PostStore::readVolume(int frame) const {
    requireListed(frame);
    return WaterVolumeFile::read(dir_ + "/" + volumeName(frame));
}

} // namespace airtrap
