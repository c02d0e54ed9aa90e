#include "post/PostStore.h"

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "io/SequenceName.h"
#include "io/VdbExporter.h"
#include "post/MeshFile.h"

#include <algorithm>
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
    if (!std::filesystem::exists(path))
        return PostStore(dir, nlohmann::json::object(), {});
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    nlohmann::json json;
    try {
        json = nlohmann::json::parse(bytes.begin(), bytes.end());
    } catch (const nlohmann::json::exception& error) {
        throw Error(ErrorKind::CacheCorrupt, path + ": not valid JSON (" + error.what() + ")");
    }
    if (!json.is_object() || json.value("format", "") != kFormatName)
        throw Error(ErrorKind::CacheCorrupt, path + ": field 'format' is not \"airtrap-post\"");
    if (json.value("format_version", 0) > kFormatVersion)
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": format_version " + json["format_version"].dump() +
                        ", this build reads " + std::to_string(kFormatVersion) + " at most");
    std::vector<PostFrameEntry> frames;
    for (const nlohmann::json& entry : json.value("frames", nlohmann::json::array()))
        frames.push_back(entryFromJson(entry, path));
    std::sort(frames.begin(), frames.end(),
              [](const PostFrameEntry& a, const PostFrameEntry& b) { return a.frame < b.frame; });
    return PostStore(dir, json.value("settings", nlohmann::json::object()), std::move(frames));
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
    const auto at = std::lower_bound(
        frames_.begin(), frames_.end(), frame,
        [](const PostFrameEntry& entry, int wanted) { return entry.frame < wanted; });
    return at != frames_.end() && at->frame == frame ? &*at : nullptr;
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
    std::error_code error;
    std::filesystem::create_directories(dir_, error);
    if (error)
        throw Error(ErrorKind::Io,
                    AtomicFile::errorMessage("cannot create folder", dir_, error.value()));
    MeshFile::write(dir_ + "/" + meshName(entry.frame), freeSurface);
    VdbExporter::write(dir_ + "/" + volumeName(entry.frame), volume, UpAxis::Y);
    const std::lock_guard lock(mutex_);
    const auto at = std::lower_bound(
        frames_.begin(), frames_.end(), entry.frame,
        [](const PostFrameEntry& listed, int wanted) { return listed.frame < wanted; });
    if (at != frames_.end() && at->frame == entry.frame)
        *at = entry;
    else
        frames_.insert(at, entry);
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
    const nlohmann::json json = {{"format", kFormatName},
                                 {"format_version", kFormatVersion},
                                 {"creator", "Airtrap " AIRTRAP_VERSION},
                                 {"settings", settings_},
                                 {"frames", frames}};
    AtomicFile::write(manifestPath(), json.dump(2) + "\n");
}

} // namespace airtrap
