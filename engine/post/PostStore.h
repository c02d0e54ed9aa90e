#pragma once
// The post stage's results, kept beside the cache in `<cache>/post/` (docs/CACHE_FORMAT.md): per
// frame the free-surface mesh (`water_0001.atm`, MeshFile) and the water volume
// (`fluid_0001.vdb`, WaterVolumeFile), listed in `post.json` with the checksum of the cache frame
// they were made from. post.json also holds the settings they were made with. A result whose
// source frame was re-baked, or whose settings changed, is stale: not current, made again by the
// next post run. Files are written atomically and listed only once complete, as the cache's own
// frames are, so a stopped run loses nothing it finished.
#include "post/ResultList.h"
#include "post/WaterVolume.h"
#include "rigid/TriangleMesh.h"

#include <cstdint>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

struct PostFrameEntry {
    int frame = 0;
    std::uint32_t sourceCrc32 = 0; //!< of the cache frame it was made from
    std::uint64_t triangles = 0;   //!< of the free-surface mesh
    double seconds = 0.0;          //!< wall time it took
    //! CRC-32 of the written mesh and volume files, so that a damaged result is made again
    //! rather than counted current (0 in a post.json written before they were kept: such a
    //! result is made again once).
    std::uint32_t waterCrc32 = 0;
    std::uint32_t fluidCrc32 = 0;

    nlohmann::json toJson() const;
    static PostFrameEntry fromJson(const nlohmann::json& json);
};

class PostStore {
public:
    static constexpr int kFormatVersion = 1;
    static constexpr const char* kFolderName = "post";
    static constexpr const char* kManifestName = "post.json";
    static constexpr const char* kPartsFolderName = "parts";

    //! The store of the cache in `cacheDir`; empty (nothing listed, no folder yet) when no post
    //! run has finished a frame. A damaged post.json → Error(CacheCorrupt) naming it.
    static PostStore open(const std::string& cacheDir);
    //! open(), or an empty store when post.json is damaged (`damage` says how): what it listed
    //! is made again by the run that writes into it.
    static PostStore openOrEmpty(const std::string& cacheDir, std::string& damage);

    //! The store as a run that writes only some frames sees it while other runs write other
    //! frames at once (a farm's job array, docs/FARM.md): it starts with post.json's list (or an
    //! empty one when post.json is damaged, `damage` says how) but lists what it makes in
    //! post/parts/`part`.json only, so no run rewrites another's entries. The next run that is
    //! not a part merges the parts (mergeParts()). `part` is letters, digits, '-' and '_'
    //! (Error(InvalidInput) otherwise).
    static PostStore openPart(const std::string& cacheDir, const std::string& part,
                              std::string& damage);

    PostStore(PostStore&& other) noexcept;
    PostStore(const PostStore&) = delete;
    PostStore& operator=(const PostStore&) = delete;

    //! Adopts `settings` (the render settings as JSON). When they differ from the listed results'
    //! settings, every listed frame is unlisted: made with other settings, it is stale.
    void useSettings(const nlohmann::json& settings);
    const nlohmann::json& settings() const { return results_.settings(); }

    //! True when `frame` is listed, was made from the cache frame with this checksum, and both
    //! its files still hold what was written (their CRC-32 as listed).
    bool isCurrent(int frame, std::uint32_t sourceCrc32) const;
    //! True when `frame` is listed as made from the cache frame with this checksum. Unlike
    //! isCurrent() it reads no file: cheap enough to mark every frame of a timeline.
    bool isListedFrom(int frame, std::uint32_t sourceCrc32) const;
    //! "<path>: <reason>" for each listed result whose file is missing or no longer matches its
    //! listed CRC-32 (`airtrap-cli check`).
    std::vector<std::string> verify() const;
    bool hasFrame(int frame) const;
    std::vector<int> frames() const;

    //! Writes both files, then lists the frame. Safe to call from several threads at once.
    //! Error(Io) (disk full, permission denied) leaves the frame unlisted.
    void writeFrame(const PostFrameEntry& entry, const TriangleMesh& freeSurface,
                    const WaterVolume& volume);
    //! Lists the entries of every part list in post/parts/ that were made with this store's
    //! settings and whose files match their checksums (the rest is made again), then deletes
    //! the part lists. Returns how many frames it listed; "<path>: <reason>" in `damaged` for
    //! each part list that could not be read. Call it only when no part run is under way.
    int mergeParts(std::vector<std::string>& damaged);

    //! Listed results; a damaged file → Error(CacheCorrupt) naming it, an unlisted frame →
    //! Error(InvalidInput) saying to run `post`.
    TriangleMesh readFreeSurface(int frame) const;
    WaterVolume readVolume(int frame) const;

    const std::string& directory() const { return dir_; }
    const std::string& manifestPath() const { return results_.path(); }

private:
    PostStore(std::string dir, ResultList<PostFrameEntry> results);
    void requireListed(int frame) const;
    //! mergeParts() for one part list; returns how many frames it listed.
    int mergePart(const std::string& partPath, std::vector<std::string>& damaged);
    //! "<path>: <reason>" when a file of `entry` is missing or differs from its listed CRC-32,
    //! else "".
    std::string damageOf(const PostFrameEntry& entry) const;

    std::string dir_;
    ResultList<PostFrameEntry> results_;
    mutable std::mutex mutex_;
};

} // namespace airtrap
