#pragma once
// manifest.json of a cache folder (docs/CACHE_FORMAT.md): what was baked (a copy of the scene and
// its parameter hash), at what rate, which frames exist with their sizes and checksums, and how
// the bake ended. The frame list is the authority: a frame file it does not list is not part of
// the cache.
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

//! One listed frame file.
struct CacheFrameEntry {
    int frame = 0;           //!< 1 = the initial state
    std::string file;        //!< name inside the cache folder, e.g. "frame_0001.atf"
    std::uint64_t bytes = 0; //!< size of the whole file
    std::uint32_t crc32 = 0; //!< CRC-32 (zlib polynomial) of the whole file

    bool operator==(const CacheFrameEntry& other) const = default;
};

struct CacheManifest {
    static constexpr int kFormatVersion = 2;
    //! Value of the "format" field; tells a cache manifest from any other manifest.json.
    static constexpr const char* kFormatName = "airtrap-cache";
    static constexpr const char* kFileName = "manifest.json";

    int formatVersion = kFormatVersion;
    std::string creator = "Airtrap " AIRTRAP_VERSION; //!< the build that created the cache
    nlohmann::json scene = nlohmann::json::object();  //!< copy of the baked scene's JSON
    std::string parameterHash; //!< hash of the parameters that change the result (the caller's)
    double fps = 0.0;
    std::vector<CacheFrameEntry> frames; //!< sorted by frame number, no duplicates
    //! "baking", "complete", "stopped" or "failed: <reason>".
    std::string status = "baking";
    //! Top-level fields written by a newer build; kept so rewriting does not drop them.
    nlohmann::json extraFields = nlohmann::json::object();

    bool operator==(const CacheManifest& other) const = default;

    nlohmann::json toJson() const;
    //! Validates every field; throws Error(CacheCorrupt, "<path>: field '<name>' ...").
    static CacheManifest fromJson(const nlohmann::json& json, const std::string& pathForMessages);

    //! Reads and validates a manifest file. Missing or unreadable → Error(Io) naming it.
    static CacheManifest read(const std::string& path);
    //! True when the file at `path` parses and declares a format version above this build's:
    //! not damage but a cache this build must leave alone.
    static bool isFromANewerBuild(const std::string& path);
    //! Writes atomically (AtomicFile); Error(Io) on failure, the old file stays intact.
    void write(const std::string& path) const;

    //! The entry of `frame`, or null.
    const CacheFrameEntry* findFrame(int frame) const;
    //! Inserts in order, replacing an entry with the same frame number.
    void setFrame(const CacheFrameEntry& entry);
    //! Drops the entry of `frame`; false when there was none.
    bool removeFrame(int frame);
    //! Drops the entries after `frame` and returns them.
    std::vector<CacheFrameEntry> removeFramesAfter(int frame);
};

} // namespace airtrap
