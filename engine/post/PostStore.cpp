#include "post/PostStore.h"

#include "core/Error.h"
#include "io/SequenceName.h"
#include "io/VdbExporter.h"
#include "post/FrameEntries.h"
#include "post/ManifestJson.h"
#include "post/MeshFile.h"

#include <filesystem>

namespace airtrap {

namespace {

constexpr const char* kFormatName = "airtrap-post";

std::string meshName(int frame) {
    return sequenceFileName("water", frame, "atm");
}
std::string volumeName(int frame) {
    return sequenceFileName("fluid", frame, "vdb");
}

nlohmann::json entryToJson(const PostFrameEntry& entry) {
    return {{"frame", entry.frame},           {"source_crc32", entry.sourceCrc32},
            {"water", meshName(entry.frame)}, {"fluid", volumeName(entry.frame)},
            {"triangles", entry.triangles},   {"seconds", entry.seconds}};
}

PostFrameEntry entryFromJson(const nlohmann::json& json, const std::string& path) {
    try {
        PostFrameEntry entry;
        entry.frame = json.at("frame").get<int>();
        entry.sourceCrc32 = json.at("source_crc32").get<std::uint32_t>();
        entry.triangles = json.at("triangles").get<std::uint64_t>();
        entry.seconds = json.at("seconds").get<double>();
        if (entry.frame < 1)
            throw Error(ErrorKind::CacheCorrupt, path + ": frame " + std::to_string(entry.frame));
        return entry;
    } catch (const nlohmann::json::exception& error) {
        throw Error(ErrorKind::CacheCorrupt, path + ": a frame entry: " + error.what());
    }
}

} // namespace

PostStore::PostStore(std::string dir, nlohmann::json settings, std::vector<PostFrameEntry> frames)
    : dir_(std::move(dir)), settings_(std::move(settings)), frames_(std::move(frames)) {}

PostStore::PostStore(PostStore&& other) noexcept
    : dir_(std::move(other.dir_)), settings_(std::move(other.settings_)),
      frames_(std::move(other.frames_)) {}

PostStore PostStore::open(const std::string& cacheDir) {
    const std::string dir = (std::filesystem::path(cacheDir) / kFolderName).string();
    const std::string path = dir + "/" + kManifestName;
    const std::optional<nlohmann::json> json = readManifestJson(path, kFormatName, kFormatVersion);
    if (!json)
        return PostStore(dir, nlohmann::json::object(), {});
    std::vector<PostFrameEntry> frames;
    for (const nlohmann::json& entry : json->value("frames", nlohmann::json::array()))
        frames.push_back(entryFromJson(entry, path));
    sortByFrame(frames);
    return PostStore(dir, json->value("settings", nlohmann::json::object()), std::move(frames));
}

std::string PostStore::manifestPath() const {
    return dir_ + "/" + kManifestName;
}

void PostStore::useSettings(const nlohmann::json& settings) {
    const std::lock_guard lock(mutex_);
    if (settings == settings_)
        return;
    settings_ = settings;
    frames_.clear();
    if (std::filesystem::exists(manifestPath()))
        writeManifest();
}

const PostFrameEntry* PostStore::find(int frame) const {
    return findFrame(frames_, frame);
}

bool PostStore::isCurrent(int frame, std::uint32_t sourceCrc32) const {
    const std::lock_guard lock(mutex_);
    const PostFrameEntry* entry = find(frame);
    return entry != nullptr && entry->sourceCrc32 == sourceCrc32;
}

bool PostStore::hasFrame(int frame) const {
    const std::lock_guard lock(mutex_);
    return find(frame) != nullptr;
}

std::vector<int> PostStore::frames() const {
    const std::lock_guard lock(mutex_);
    std::vector<int> listed;
    for (const PostFrameEntry& entry : frames_)
        listed.push_back(entry.frame);
    return listed;
}

void PostStore::writeFrame(const PostFrameEntry& entry, const TriangleMesh& freeSurface,
                           const WaterVolume& volume) {
    createResultFolder(dir_);
    MeshFile::write(dir_ + "/" + meshName(entry.frame), freeSurface);
    VdbExporter::write(dir_ + "/" + volumeName(entry.frame), volume, UpAxis::Y);
    const std::lock_guard lock(mutex_);
    putFrame(frames_, entry);
    writeManifest();
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
    return VdbExporter::read(dir_ + "/" + volumeName(frame));
}

void PostStore::writeManifest() const {
    nlohmann::json frames = nlohmann::json::array();
    for (const PostFrameEntry& entry : frames_)
        frames.push_back(entryToJson(entry));
    writeManifestJson(manifestPath(), kFormatName, kFormatVersion, settings_, frames);
}

} // namespace airtrap
