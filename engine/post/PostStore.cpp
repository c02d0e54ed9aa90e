#include "post/PostStore.h"

#include "cache/FrameFile.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "post/ManifestJson.h"
#include "post/MeshFile.h"
#include "post/SequenceName.h"
#include "post/WaterVolumeFile.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace airtrap {

namespace {

//! The checksum post.json lists for a result file's bytes. A water mesh ends in the CRC-32 of
//! the bytes before it, and the CRC-32 of data followed by its own CRC-32 is one constant for
//! every file, which would tell no mesh from another: for a file that ends in its own CRC-32 the
//! list holds the CRC-32 of the bytes before that trailer.
std::uint32_t listedCrc32(const std::vector<std::uint8_t>& bytes, bool endsInItsOwnCrc) {
    const std::size_t covered =
        endsInItsOwnCrc && bytes.size() >= 4 ? bytes.size() - 4 : bytes.size();
    return computeCrc32(bytes.data(), covered);
}

//! What an older build listed for every mesh: the CRC-32 of a whole file that ends in its own.
constexpr std::uint32_t kSelfCheckedResidue = 0x2144DF1C;

std::uint32_t fileCrc32(const std::string& path, bool endsInItsOwnCrc) {
    return listedCrc32(AtomicFile::read(path), endsInItsOwnCrc);
}

constexpr const char* kPostFormatName = "airtrap-post";

std::string meshName(int frame) {
    return sequenceFileName("water", frame, "atm");
}
std::string volumeName(int frame) {
    return sequenceFileName("fluid", frame, "vdb");
}

} // namespace

nlohmann::json PostFrameEntry::toJson() const {
    return {{"frame", frame},
            {"source_crc32", sourceCrc32},
            {"water", meshName(frame)},
            {"fluid", volumeName(frame)},
            {"triangles", triangles},
            {"seconds", seconds},
            {"water_crc32", waterCrc32},
            {"fluid_crc32", fluidCrc32}};
}

PostFrameEntry PostFrameEntry::fromJson(const nlohmann::json& json) {
    return {json.at("frame").get<int>(),
            json.at("source_crc32").get<std::uint32_t>(),
            json.at("triangles").get<std::uint64_t>(),
            json.at("seconds").get<double>(),
            json.value("water_crc32", std::uint32_t(0)),
            json.value("fluid_crc32", std::uint32_t(0))};
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

PostStore PostStore::openOrEmpty(const std::string& cacheDir, std::string& damage) {
    const std::string dir = (std::filesystem::path(cacheDir) / kFolderName).string();
    return PostStore(dir, ResultList<PostFrameEntry>::openOrEmpty(
                              dir + "/" + kManifestName, kPostFormatName, kFormatVersion, damage));
}

PostStore PostStore::openPart(const std::string& cacheDir, const std::string& part,
                              std::string& damage) {
    const bool plain =
        !part.empty() && part.size() <= 64 && std::all_of(part.begin(), part.end(), [](char c) {
            return std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_';
        });
    if (!plain)
        throw Error(ErrorKind::InvalidInput,
                    "part name '" + part +
                        "': expected 1 to 64 letters, digits, '-' or '_' (it names a file)");
    PostStore store = openOrEmpty(cacheDir, damage);
    const std::string partsDir = store.dir_ + "/" + kPartsFolderName;
    createResultFolder(partsDir);
    store.results_.moveTo(partsDir + "/" + part + ".json");
    return store;
}

int PostStore::mergeParts(std::vector<std::string>& damaged) {
    const std::filesystem::path partsDir = std::filesystem::path(dir_) / kPartsFolderName;
    std::error_code error;
    if (!std::filesystem::is_directory(partsDir, error))
        return 0;
    std::vector<std::filesystem::path> parts;
    std::filesystem::directory_iterator item(partsDir, error);
    for (; !error && item != std::filesystem::directory_iterator(); item.increment(error))
        if (item->path().extension() == ".json")
            parts.push_back(item->path());
    if (error)
        throw Error(ErrorKind::Io, AtomicFile::errorMessage("cannot list folder", partsDir.string(),
                                                            error.value()));
    std::sort(parts.begin(), parts.end());
    int merged = 0;
    for (const std::filesystem::path& part : parts) {
        merged += mergePart(part.string(), damaged);
        std::filesystem::remove(part, error);
    }
    std::filesystem::remove(partsDir, error);
    return merged;
}

int PostStore::mergePart(const std::string& partPath, std::vector<std::string>& damaged) {
    std::string damage;
    const auto part =
        ResultList<PostFrameEntry>::openOrEmpty(partPath, kPostFormatName, kFormatVersion, damage);
    if (!damage.empty())
        damaged.push_back(damage);
    if (part.settings() != settings())
        return 0;
    int merged = 0;
    for (const PostFrameEntry& entry : part.entries()) {
        const PostFrameEntry* listed = results_.find(entry.frame);
        const bool known = listed != nullptr && listed->sourceCrc32 == entry.sourceCrc32 &&
                           listed->waterCrc32 == entry.waterCrc32 &&
                           listed->fluidCrc32 == entry.fluidCrc32;
        if (known || !damageOf(entry).empty())
            continue;
        const std::lock_guard lock(mutex_);
        results_.put(entry);
        ++merged;
    }
    return merged;
}

void PostStore::useSettings(const nlohmann::json& settings) {
    const std::lock_guard lock(mutex_);
    results_.useSettings(settings);
}

bool PostStore::isCurrent(int frame, std::uint32_t sourceCrc32) const {
    PostFrameEntry entry;
    {
        const std::lock_guard lock(mutex_);
        const PostFrameEntry* listed = results_.find(frame);
        if (listed == nullptr || listed->sourceCrc32 != sourceCrc32)
            return false;
        entry = *listed;
    }
    return damageOf(entry).empty();
}

bool PostStore::isListedFrom(int frame, std::uint32_t sourceCrc32) const {
    const std::lock_guard lock(mutex_);
    const PostFrameEntry* listed = results_.find(frame);
    return listed != nullptr && listed->sourceCrc32 == sourceCrc32;
}

std::string PostStore::damageOf(const PostFrameEntry& entry) const {
    const struct {
        std::string path;
        std::uint32_t listed;
        bool endsInItsOwnCrc;
    } files[] = {{dir_ + "/" + meshName(entry.frame), entry.waterCrc32, true},
                 {dir_ + "/" + volumeName(entry.frame), entry.fluidCrc32, false}};
    for (const auto& [path, listed, endsInItsOwnCrc] : files) {
        std::vector<std::uint8_t> bytes;
        try {
            bytes = AtomicFile::read(path);
        } catch (const Error&) {
            return path + ": missing or unreadable (listed in " + manifestPath() + ")";
        }
        if (listedCrc32(bytes, endsInItsOwnCrc) != listed)
            return path + ": does not match " + manifestPath() +
                   (listed == 0 || (endsInItsOwnCrc && listed == kSelfCheckedResidue)
                        ? " (listed without a usable checksum by an older build)"
                        : " (checksum mismatch)");
    }
    return {};
}

std::vector<std::string> PostStore::verify() const {
    std::vector<PostFrameEntry> entries;
    {
        const std::lock_guard lock(mutex_);
        for (const int frame : results_.frames())
            entries.push_back(*results_.find(frame));
    }
    std::vector<std::string> problems;
    for (const PostFrameEntry& entry : entries)
        if (std::string problem = damageOf(entry); !problem.empty())
            problems.push_back(std::move(problem));
    return problems;
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
    const std::string meshPath = dir_ + "/" + meshName(entry.frame);
    const std::string volumePath = dir_ + "/" + volumeName(entry.frame);
    MeshFile::write(meshPath, freeSurface);
    WaterVolumeFile::write(volumePath, volume, UpAxis::Y);
    PostFrameEntry listed = entry;
    // Read back: the checksums of what is on disk, which is what a later run verifies.
    listed.waterCrc32 = fileCrc32(meshPath, true);
    listed.fluidCrc32 = fileCrc32(volumePath, false);
    const std::lock_guard lock(mutex_);
    results_.put(listed);
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
    PostFrameEntry entry;
    {
        const std::lock_guard lock(mutex_);
        entry = *results_.find(frame);
    }
    // Checked against its listed CRC-32 before OpenVDB sees it: OpenVDB trusts the sizes in a
    // file, and a damaged one asked it for 140 TB (found by the sanitizer build).
    const std::string path = dir_ + "/" + volumeName(frame);
    if (entry.fluidCrc32 != 0 && fileCrc32(path, false) != entry.fluidCrc32)
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": does not match " + manifestPath() + " (checksum mismatch)");
    return WaterVolumeFile::read(path);
}

} // namespace airtrap
