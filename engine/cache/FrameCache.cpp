#include "cache/FrameCache.h"

#include "cache/FrameValueCheck.h"
#include "core/AtomicFile.h"
#include "core/Error.h"
#include "scene/SceneJson.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <unistd.h>

namespace airtrap {
namespace {

namespace fs = std::filesystem;

std::string withoutTrailingSlash(std::string dir) {
    while (dir.size() > 1 && dir.back() == '/')
        dir.pop_back();
    return dir;
}

bool startsWith(const std::string& text, const std::string& prefix) {
    return text.compare(0, prefix.size(), prefix) == 0;
}

//! The frame number of a "frame_<digits>.atf" name, or -1 for any other name.
int frameNumberOf(const std::string& name) {
    const std::string prefix = "frame_";
    const std::string suffix = ".atf";
    if (name.size() <= prefix.size() + suffix.size() || !startsWith(name, prefix) ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
        return -1;
    const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - 4);
    if (digits.size() > 9 || digits.find_first_not_of("0123456789") != std::string::npos)
        return -1;
    return std::stoi(digits);
}

//! Temporaries of AtomicFile for our own files only: a user's "notes.tmp" is not ours to delete.
bool isCacheTemporary(const std::string& name) {
    return AtomicFile::isTemporaryName(name) &&
           (startsWith(name, "frame_") || startsWith(name, CacheManifest::kFileName));
}

std::vector<std::string> folderEntries(const std::string& dir) {
    std::error_code error;
    std::vector<std::string> names;
    for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error))
        names.push_back(it->path().filename().string());
    if (error)
        throw Error(ErrorKind::Io, AtomicFile::errorMessage("cannot list", dir, error.value()));
    return names;
}

void removeFile(const std::string& path) {
    if (::unlink(path.c_str()) != 0 && errno != ENOENT)
        throw Error(ErrorKind::Io, AtomicFile::errorMessage("cannot delete", path, errno));
}

void createFolder(const std::string& dir) {
    std::error_code error;
    fs::create_directories(dir, error);
    if (!error && !fs::is_directory(dir, error))
        error = std::make_error_code(std::errc::not_a_directory);
    if (error)
        throw Error(ErrorKind::Io,
                    AtomicFile::errorMessage("cannot create cache folder", dir, error.value()));
}

//! Clears an old cache for overwriting. The manifest goes first: once it is gone the folder is
//! no longer a cache, so an interruption half-way leaves no cache listing deleted frames.
void clearOldCache(const std::string& dir, const std::vector<std::string>& names) {
    removeFile(dir + "/" + CacheManifest::kFileName);
    for (const std::string& name : names)
        if (frameNumberOf(name) >= 0 || isCacheTemporary(name))
            removeFile(dir + "/" + name);
}

bool holdsCache(const std::vector<std::string>& names) {
    for (const std::string& name : names)
        if (name == CacheManifest::kFileName || frameNumberOf(name) >= 0)
            return true;
    return false;
}

std::string hex32(std::uint32_t value) {
    char text[11];
    std::snprintf(text, sizeof text, "0x%08x", value);
    return text;
}

[[noreturn]] void corruptCache(const std::string& path, const std::string& what) {
    throw Error(ErrorKind::CacheCorrupt, path + ": " + what);
}

//! Reads a listed frame file; a missing one is damage to the cache, not an I/O failure.
std::vector<std::uint8_t> readListedFile(const std::string& path) {
    try {
        return AtomicFile::read(path);
    } catch (const Error&) {
        std::error_code error;
        if (!fs::exists(path, error) && !error)
            corruptCache(path, "missing (listed in " + std::string(CacheManifest::kFileName) + ")");
        throw;
    }
}

void checkAgainstEntry(const std::vector<std::uint8_t>& bytes, const CacheFrameEntry& entry,
                       const std::string& path) {
    const std::uint32_t crc = computeCrc32(bytes.data(), bytes.size());
    if (bytes.size() != entry.bytes || crc != entry.crc32)
        corruptCache(path, "does not match " + std::string(CacheManifest::kFileName) +
                               " (expected " + std::to_string(entry.bytes) + " bytes, CRC-32 " +
                               hex32(entry.crc32) + "; found " + std::to_string(bytes.size()) +
                               " bytes, CRC-32 " + hex32(crc) + ")");
}

//! The domain of the manifest's scene, or nothing when that scene does not read (a manifest
//! from a newer build): its frames are then checked for finite values only.
std::optional<Aabb> sceneDomain(const nlohmann::json& scene) {
    try {
        return sceneFromJson(scene, CacheManifest::kFileName).domain();
    } catch (const Error&) {
        return std::nullopt;
    }
}

//! How far outside the domain a frame may hold water: the simulation removes water beyond one
//! support radius at the start of every step, and no step carries it further than a fraction of
//! the domain, so a whole domain's size off is not something a bake wrote.
double domainMargin(const Aabb& domain) {
    return domain.size().maxCoeff();
}

} // namespace

FrameCache::FrameCache(std::string dir, CacheManifest manifest)
    : dir_(std::move(dir)), manifest_(std::move(manifest)), domain_(sceneDomain(manifest_.scene)) {}

FrameCache::FrameCache(FrameCache&& other) noexcept {
    const std::lock_guard lock(other.mutex_);
    dir_ = std::move(other.dir_);
    manifest_ = std::move(other.manifest_);
    domain_ = other.domain_;
}

FrameCache& FrameCache::operator=(FrameCache&& other) noexcept {
    if (this != &other) {
        const std::scoped_lock lock(mutex_, other.mutex_);
        dir_ = std::move(other.dir_);
        manifest_ = std::move(other.manifest_);
        domain_ = other.domain_;
    }
    return *this;
}

FrameCache FrameCache::create(const std::string& dir, const nlohmann::json& sceneJson,
                              const std::string& parameterHash, double fps, bool overwrite) {
    if (!std::isfinite(fps) || fps <= 0.0)
        throw Error(ErrorKind::InvalidInput,
                    "cache fps must be positive, got " + std::to_string(fps));
    const std::string folder = withoutTrailingSlash(dir);
    createFolder(folder);
    const std::vector<std::string> names = folderEntries(folder);
    if (holdsCache(names)) {
        const bool manifestLost =
            std::find(names.begin(), names.end(), CacheManifest::kFileName) == names.end();
        if (!overwrite && manifestLost)
            throw Error(ErrorKind::InvalidInput,
                        folder + " holds frame files but no " + CacheManifest::kFileName +
                            "; continue them with --resume (it lists them again) or start "
                            "again with --overwrite");
        if (!overwrite)
            throw Error(ErrorKind::InvalidInput,
                        folder + " already holds an Airtrap cache; choose another folder or "
                                 "allow overwriting it");
        clearOldCache(folder, names);
    }
    CacheManifest manifest;
    manifest.scene = sceneJson;
    manifest.parameterHash = parameterHash;
    manifest.fps = fps;
    manifest.status = "baking";
    manifest.write(folder + "/" + CacheManifest::kFileName);
    return FrameCache(folder, std::move(manifest));
}

FrameCache FrameCache::open(const std::string& dir) {
    const std::string folder = withoutTrailingSlash(dir);
    const std::string path = folder + "/" + CacheManifest::kFileName;
    if (::access(path.c_str(), F_OK) != 0 && errno == ENOENT) {
        if (holdsFrameFiles(folder))
            throw Error(ErrorKind::InvalidInput,
                        "not an Airtrap cache: " + path +
                            " missing, though the folder holds frame files; `airtrap-cli bake "
                            "SCENE --out " +
                            folder + " --resume` lists them again and continues the bake");
        throw Error(ErrorKind::InvalidInput, "not an Airtrap cache: " + path + " missing");
    }
    return FrameCache(folder, CacheManifest::read(path));
}

bool FrameCache::holdsFrameFiles(const std::string& dir) {
    std::error_code error;
    if (!fs::is_directory(dir, error))
        return false;
    const std::vector<std::string> names = folderEntries(withoutTrailingSlash(dir));
    return std::any_of(names.begin(), names.end(),
                       [](const std::string& name) { return frameNumberOf(name) >= 0; });
}

FrameCache FrameCache::rebuild(const std::string& dir, const nlohmann::json& sceneJson,
                               const std::string& parameterHash, double fps, const std::string& why,
                               std::vector<std::string>& notes) {
    const std::string folder = withoutTrailingSlash(dir);
    CacheManifest manifest;
    manifest.scene = sceneJson;
    manifest.parameterHash = parameterHash;
    manifest.fps = fps;
    manifest.status = "stopped";
    for (int frame = 1;; ++frame) {
        const std::string name = frameFileName(frame);
        const std::string path = folder + "/" + name;
        if (::access(path.c_str(), F_OK) != 0)
            break;
        const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
        try {
            const FrameData data = decodeFrame(bytes, path);
            // The bake lands every frame on (n − 1) / fps exactly (docs/CACHE_FORMAT.md).
            if (data.state.frame != frame || data.state.time != double(frame - 1) / fps)
                corruptCache(path, "holds t = " + std::to_string(data.state.time) +
                                       " s, not frame " + std::to_string(frame) +
                                       " of this scene at " + std::to_string(fps) + " fps");
        } catch (const Error& error) {
            if (error.kind() != ErrorKind::CacheCorrupt)
                throw;
            notes.push_back(std::string(error.what()) + "; not listed, baked again");
            break;
        }
        manifest.setFrame({frame, name, bytes.size(), computeCrc32(bytes.data(), bytes.size())});
    }
    manifest.write(folder + "/" + CacheManifest::kFileName);
    notes.push_back(std::string(CacheManifest::kFileName) + " " + why + ": rebuilt from " +
                    std::to_string(manifest.frames.size()) + " frame file(s) that verify");
    return FrameCache(folder, std::move(manifest));
}

bool FrameCache::isCache(const std::string& dir) {
    const std::string path = withoutTrailingSlash(dir) + "/" + CacheManifest::kFileName;
    return ::access(path.c_str(), F_OK) == 0;
}

template <typename Change>
void FrameCache::updateManifest(Change&& change) {
    CacheManifest updated = manifest_;
    change(updated);
    updated.write(manifestPath());
    manifest_ = std::move(updated);
}

void FrameCache::writeFrame(const SimulationState& state, const FrameStats& stats) {
    if (state.frame < 1)
        throw Error(ErrorKind::InvalidInput,
                    "cannot cache frame " + std::to_string(state.frame) + " (frames start at 1)");
    const std::vector<std::uint8_t> bytes = encodeFrame(state, stats);
    const CacheFrameEntry entry{state.frame, frameFileName(state.frame), bytes.size(),
                                computeCrc32(bytes.data(), bytes.size())};
    {
        // Re-writing a listed frame: unlist it first, so that a failure between the file and the
        // manifest write never leaves an entry whose size and CRC describe the old file.
        const std::lock_guard lock(mutex_);
        const CacheFrameEntry* old = manifest_.findFrame(entry.frame);
        if (old && *old != entry)
            updateManifest([&](CacheManifest& m) { m.removeFrame(entry.frame); });
    }
    // The file is written without the lock: readers of other frames need not wait for it.
    AtomicFile::write(dir_ + "/" + entry.file, bytes);
    const std::lock_guard lock(mutex_);
    updateManifest([&](CacheManifest& m) { m.setFrame(entry); });
}

CacheFrameEntry FrameCache::entryOf(int frame) const {
    const std::lock_guard lock(mutex_);
    const CacheFrameEntry* entry = manifest_.findFrame(frame);
    if (!entry)
        throw Error(ErrorKind::InvalidInput,
                    "frame " + std::to_string(frame) + " is not in the cache " + dir_);
    return *entry;
}

std::optional<FrameData> FrameCache::readIntactFrame(int frame, std::string& problem) const {
    try {
        return readFrame(frame);
    } catch (const Error& error) {
        if (error.kind() != ErrorKind::CacheCorrupt)
            throw;
        problem = error.what();
        return std::nullopt;
    }
}

FrameData FrameCache::readFrame(int frame) const {
    const CacheFrameEntry entry = entryOf(frame);
    const std::string path = dir_ + "/" + entry.file;
    const std::vector<std::uint8_t> bytes = readListedFile(path);
    if (bytes.size() < entry.bytes)
        corruptCache(path, "truncated: expected " + std::to_string(entry.bytes) + " bytes, found " +
                               std::to_string(bytes.size()));
    FrameData data = decodeFrame(bytes, path);
    checkAgainstEntry(bytes, entry, path);
    if (data.state.frame != frame)
        corruptCache(path, "holds frame " + std::to_string(data.state.frame) + ", expected frame " +
                               std::to_string(frame));
    const std::optional<Aabb> domain = sceneDomainSnapshot();
    if (domain)
        checkFrameLiesInDomain(data, *domain, domainMargin(*domain), path);
    return data;
}

std::vector<int> FrameCache::frames() const {
    const std::lock_guard lock(mutex_);
    std::vector<int> numbers;
    numbers.reserve(manifest_.frames.size());
    for (const CacheFrameEntry& entry : manifest_.frames)
        numbers.push_back(entry.frame);
    return numbers;
}

bool FrameCache::hasFrame(int frame) const {
    const std::lock_guard lock(mutex_);
    return manifest_.findFrame(frame) != nullptr;
}

CacheManifest FrameCache::manifestSnapshot() const {
    const std::lock_guard lock(mutex_);
    return manifest_;
}

void FrameCache::reload() {
    CacheManifest fresh = CacheManifest::read(manifestPath());
    std::optional<Aabb> domain = sceneDomain(fresh.scene);
    const std::lock_guard lock(mutex_);
    manifest_ = std::move(fresh);
    domain_ = domain;
}

std::optional<Aabb> FrameCache::sceneDomainSnapshot() const {
    const std::lock_guard lock(mutex_);
    return domain_;
}

std::string FrameCache::manifestPath() const {
    return dir_ + "/" + CacheManifest::kFileName;
}

std::string FrameCache::framePath(int frame) const {
    return dir_ + "/" + frameFileName(frame);
}

std::string FrameCache::frameFileName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "frame_%04d.atf", frame);
    return name;
}

void FrameCache::setStatus(const std::string& status) {
    const std::lock_guard lock(mutex_);
    updateManifest([&](CacheManifest& m) { m.status = status; });
}

std::string FrameCache::recordedSceneDamage() const {
    const CacheManifest recorded = manifest();
    const std::string path = manifestPath();
    std::string hash;
    try {
        hash = parameterHash(sceneFromJson(recorded.scene, path + ": scene"));
    } catch (const Error& error) {
        return path + ": the scene it records does not read back (" + error.what() + ")";
    }
    if (hash != recorded.parameterHash)
        return path + ": the scene it records has parameter hash " + hash + ", not the " +
               recorded.parameterHash + " it lists";
    return {};
}

void FrameCache::replaceScene(const nlohmann::json& sceneJson, const std::string& parameterHash) {
    const std::lock_guard lock(mutex_);
    updateManifest([&](CacheManifest& m) {
        m.scene = sceneJson;
        m.parameterHash = parameterHash;
    });
    domain_ = sceneDomain(sceneJson);
}

int FrameCache::lastGoodFrame(std::vector<std::string>* problems) const {
    const std::vector<int> listed = frames();
    for (auto it = listed.rbegin(); it != listed.rend(); ++it) {
        try {
            readFrame(*it);
            return *it;
        } catch (const Error& error) {
            if (error.kind() != ErrorKind::CacheCorrupt)
                throw;
            if (problems)
                problems->push_back(error.what());
        }
    }
    return 0;
}

int FrameCache::lastFrameBeforeDamage(std::vector<std::string>* problems) const {
    int intact = 0;
    for (const int frame : frames()) {
        if (frame != intact + 1) {
            if (problems)
                problems->push_back(framePath(intact + 1) + ": not listed in " +
                                    CacheManifest::kFileName);
            return intact;
        }
        try {
            readFrame(frame);
        } catch (const Error& error) {
            if (error.kind() != ErrorKind::CacheCorrupt)
                throw;
            if (problems)
                problems->push_back(error.what());
            return intact;
        }
        intact = frame;
    }
    return intact;
}

std::vector<std::string> FrameCache::verify() const {
    std::vector<std::string> problems;
    for (const int frame : frames()) {
        try {
            readFrame(frame);
        } catch (const Error& error) {
            if (error.kind() != ErrorKind::CacheCorrupt)
                throw;
            problems.push_back(error.what());
        }
    }
    return problems;
}

void FrameCache::truncateAfter(int frame) {
    std::vector<CacheFrameEntry> removed;
    {
        const std::lock_guard lock(mutex_);
        if (!manifest_.frames.empty() && manifest_.frames.back().frame > frame)
            updateManifest([&](CacheManifest& m) { removed = m.removeFramesAfter(frame); });
    }
    // Files go only after the manifest no longer lists them, so no reader is sent to a deleted
    // file by a fresh manifest.
    for (const CacheFrameEntry& entry : removed)
        removeFile(dir_ + "/" + entry.file);
    for (const std::string& name : folderEntries(dir_))
        if (frameNumberOf(name) > frame)
            removeFile(dir_ + "/" + name);
}

} // namespace airtrap
