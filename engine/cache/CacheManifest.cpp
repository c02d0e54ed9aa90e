#include "cache/CacheManifest.h"

#include "core/AtomicFile.h"
#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace airtrap {
namespace {

using nlohmann::json;

const char* const kKnownFields[] = {"format", "format_version", "creator", "status",
                                    "fps",    "parameter_hash", "scene",   "frames"};

[[noreturn]] void badField(const std::string& path, const std::string& field,
                           const std::string& what) {
    throw Error(ErrorKind::CacheCorrupt, path + ": field '" + field + "' " + what);
}

const json& requireField(const json& object, const char* key, const std::string& prefix,
                         const std::string& path) {
    const auto found = object.find(key);
    if (found == object.end())
        badField(path, prefix + key, "is missing");
    return *found;
}

std::string requireString(const json& object, const char* key, const std::string& prefix,
                          const std::string& path) {
    const json& value = requireField(object, key, prefix, path);
    if (!value.is_string())
        badField(path, prefix + key, "must be a string");
    return value.get<std::string>();
}

//! An integer in [low, high]; JSON numbers with a fraction are rejected.
std::int64_t requireInteger(const json& object, const char* key, const std::string& prefix,
                            const std::string& path, std::int64_t low, std::int64_t high) {
    const json& value = requireField(object, key, prefix, path);
    if (!value.is_number_integer())
        badField(path, prefix + key, "must be an integer");
    const bool isUnsigned = value.is_number_unsigned();
    const auto number =
        isUnsigned ? static_cast<std::int64_t>(std::min<std::uint64_t>(
                         value.get<std::uint64_t>(), std::numeric_limits<std::int64_t>::max()))
                   : value.get<std::int64_t>();
    if (number < low || number > high)
        badField(path, prefix + key,
                 "is " + value.dump() + ", allowed " + std::to_string(low) + " to " +
                     std::to_string(high));
    return number;
}

//! A frame file name must stay inside the cache folder: truncateAfter() deletes it.
bool isPlainFileName(const std::string& name) {
    return !name.empty() && name != "." && name != ".." && name.find('/') == std::string::npos;
}

CacheFrameEntry frameFromJson(const json& item, std::size_t index, const std::string& path) {
    const std::string prefix = "frames[" + std::to_string(index) + "].";
    if (!item.is_object())
        badField(path, prefix.substr(0, prefix.size() - 1), "must be an object");
    CacheFrameEntry entry;
    entry.frame = static_cast<int>(
        requireInteger(item, "frame", prefix, path, 1, std::numeric_limits<int>::max()));
    entry.file = requireString(item, "file", prefix, path);
    if (!isPlainFileName(entry.file))
        badField(path, prefix + "file", "must be a file name inside the cache folder");
    entry.bytes = static_cast<std::uint64_t>(
        requireInteger(item, "bytes", prefix, path, 0, std::numeric_limits<std::int64_t>::max()));
    entry.crc32 = static_cast<std::uint32_t>(
        requireInteger(item, "crc32", prefix, path, 0, std::numeric_limits<std::uint32_t>::max()));
    return entry;
}

std::vector<CacheFrameEntry> framesFromJson(const json& object, const std::string& path) {
    const json& list = requireField(object, "frames", "", path);
    if (!list.is_array())
        badField(path, "frames", "must be an array");
    std::vector<CacheFrameEntry> frames;
    for (std::size_t i = 0; i < list.size(); ++i) {
        frames.push_back(frameFromJson(list[i], i, path));
        if (i > 0 && frames[i].frame <= frames[i - 1].frame)
            badField(path, "frames[" + std::to_string(i) + "].frame", "is not in increasing order");
    }
    return frames;
}

void checkFormat(const json& object, const std::string& path) {
    if (!object.is_object())
        throw Error(ErrorKind::CacheCorrupt, path + ": not a JSON object");
    if (requireString(object, "format", "", path) != CacheManifest::kFormatName)
        badField(path, "format", std::string("must be \"") + CacheManifest::kFormatName + "\"");
    const auto version =
        requireInteger(object, "format_version", "", path, 1, std::numeric_limits<int>::max());
    if (version > CacheManifest::kFormatVersion)
        throw Error(ErrorKind::CacheCorrupt,
                    path + ": written by a newer Airtrap (cache format version " +
                        std::to_string(version) + ", this build reads up to " +
                        std::to_string(CacheManifest::kFormatVersion) + ")");
}

} // namespace

json CacheManifest::toJson() const {
    json object = extraFields.is_object() ? extraFields : json::object();
    object["format"] = kFormatName;
    object["format_version"] = formatVersion;
    object["creator"] = creator;
    object["status"] = status;
    object["fps"] = fps;
    object["parameter_hash"] = parameterHash;
    object["scene"] = scene;
    json list = json::array();
    for (const CacheFrameEntry& entry : frames)
        list.push_back({{"frame", entry.frame},
                        {"file", entry.file},
                        {"bytes", entry.bytes},
                        {"crc32", entry.crc32}});
    object["frames"] = std::move(list);
    return object;
}

CacheManifest CacheManifest::fromJson(const json& object, const std::string& path) {
    checkFormat(object, path);
    CacheManifest manifest;
    manifest.formatVersion = static_cast<int>(object.at("format_version").get<std::int64_t>());
    manifest.creator = requireString(object, "creator", "", path);
    manifest.status = requireString(object, "status", "", path);
    const json& fps = requireField(object, "fps", "", path);
    if (!fps.is_number() || !std::isfinite(fps.get<double>()) || fps.get<double>() <= 0.0)
        badField(path, "fps", "must be a positive number");
    manifest.fps = fps.get<double>();
    manifest.parameterHash = requireString(object, "parameter_hash", "", path);
    manifest.scene = requireField(object, "scene", "", path);
    if (!manifest.scene.is_object())
        badField(path, "scene", "must be an object");
    manifest.frames = framesFromJson(object, path);
    manifest.extraFields = object;
    for (const char* key : kKnownFields)
        manifest.extraFields.erase(key);
    return manifest;
}

CacheManifest CacheManifest::read(const std::string& path) {
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    json object;
    try {
        object = json::parse(bytes.begin(), bytes.end());
    } catch (const json::parse_error& error) {
        throw Error(ErrorKind::CacheCorrupt, path + ": not valid JSON (" + error.what() + ")");
    }
    return fromJson(object, path);
}

bool CacheManifest::isFromANewerBuild(const std::string& path) {
    try {
        const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
        const json object = json::parse(bytes.begin(), bytes.end());
        const auto version = object.find("format_version");
        return version != object.end() && version->is_number_integer() &&
               version->get<long long>() > kFormatVersion;
    } catch (const std::exception&) {
        return false;
    }
}

void CacheManifest::write(const std::string& path) const {
    AtomicFile::write(path, toJson().dump(2) + "\n");
}

const CacheFrameEntry* CacheManifest::findFrame(int frame) const {
    const auto found = std::lower_bound(
        frames.begin(), frames.end(), frame,
        [](const CacheFrameEntry& entry, int number) { return entry.frame < number; });
    return found != frames.end() && found->frame == frame ? &*found : nullptr;
}

void CacheManifest::setFrame(const CacheFrameEntry& entry) {
    const auto at = std::lower_bound(
        frames.begin(), frames.end(), entry.frame,
        [](const CacheFrameEntry& item, int number) { return item.frame < number; });
    if (at != frames.end() && at->frame == entry.frame)
        *at = entry;
    else
        frames.insert(at, entry);
}

bool CacheManifest::removeFrame(int frame) {
    const CacheFrameEntry* entry = findFrame(frame);
    if (!entry)
        return false;
    frames.erase(frames.begin() + (entry - frames.data()));
    return true;
}

std::vector<CacheFrameEntry> CacheManifest::removeFramesAfter(int frame) {
    const auto first = std::upper_bound(
        frames.begin(), frames.end(), frame,
        [](int number, const CacheFrameEntry& entry) { return number < entry.frame; });
    std::vector<CacheFrameEntry> removed(first, frames.end());
    frames.erase(first, frames.end());
    return removed;
}

} // namespace airtrap
