#pragma once
// The sub-grid bubbles the post stage made, kept beside the cache in `<cache>/post/`
// (docs/CACHE_FORMAT.md): per frame a SubgridFile (`subgrid_0001.atb`), listed in `subgrid.json`
// with the frame's chain checksum, and the settings they were made with. A frame's bubbles come
// from every frame before it, so its chain checksum folds in the checksums of all cache frames up
// to it: re-baking any earlier frame makes it stale. Separate from the surface results' post.json
// so that tuning the sub-grid bubbles never throws away the slower water meshes.
#include "cache/CacheManifest.h"
#include "post/ResultList.h"
#include "post/SubgridFrame.h"

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

struct SubgridFrameEntry {
    int frame = 0;
    std::uint32_t chainCrc32 = 0; //!< chainCrc32 of the cache frames up to this one
    std::uint32_t bubbles = 0;    //!< how many sub-grid bubbles the frame holds

    nlohmann::json toJson() const;
    static SubgridFrameEntry fromJson(const nlohmann::json& json);
};

class SubgridStore {
public:
    static constexpr int kFormatVersion = 1;
    static constexpr const char* kManifestName = "subgrid.json";

    //! The store of the cache in `cacheDir`; empty when no post run has made sub-grid bubbles. A
    //! damaged subgrid.json → Error(CacheCorrupt) naming it.
    static SubgridStore open(const std::string& cacheDir);
    //! open(), or an empty store when subgrid.json is damaged (`damage` says how).
    static SubgridStore openOrEmpty(const std::string& cacheDir, std::string& damage);

    //! Folds a cache frame's checksum into the chain of the frames before it (0 for the first).
    static std::uint32_t chainCrc32(std::uint32_t previousChain, std::uint32_t frameCrc32);

    //! Adopts `settings`; when they differ from the listed frames' settings, all are unlisted.
    void useSettings(const nlohmann::json& settings);

    //! Listed with this chain, and its file is whole: a damaged file is made again.
    bool isCurrent(int frame, std::uint32_t chainCrc32) const;
    //! The file of a listed frame reads back (magic, version, its own CRC-32).
    bool isIntact(int frame) const;
    //! isCurrent() with the chain of `manifest`'s frames up to `frame`; false when it is not
    //! listed there.
    bool isCurrentIn(const CacheManifest& manifest, int frame) const;
    bool hasFrame(int frame) const;
    //! The listed entry of `frame`, or null.
    const SubgridFrameEntry* entry(int frame) const;
    std::vector<int> frames() const;

    //! Writes the frame's file, then lists it. Error(Io) leaves it unlisted.
    void writeFrame(const SubgridFrameEntry& entry, const SubgridFrame& bubbles);
    //! A listed frame's bubbles; a damaged or missing file → Error(CacheCorrupt) naming it, an
    //! unlisted one
    //! → Error(InvalidInput) saying to run `post`.
    SubgridFrame readFrame(int frame) const;

    const std::string& directory() const { return dir_; }
    const std::string& manifestPath() const { return results_.path(); }

private:
    SubgridStore(std::string dir, ResultList<SubgridFrameEntry> results);

    std::string dir_;
    ResultList<SubgridFrameEntry> results_;
};

} // namespace airtrap
