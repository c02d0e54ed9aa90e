#pragma once
// The per-frame results a post store lists in its JSON manifest (`post/post.json`,
// `post/subgrid.json`; docs/CACHE_FORMAT.md "Post results"): one entry per frame, sorted by
// frame, and the settings they were all made with. Adopting other settings unlists every entry:
// made with the old ones, they are stale. `Entry` has an `int frame`, a `toJson() const` and a
// `static Entry fromJson(const nlohmann::json&)`, which may throw nlohmann's exceptions: a
// reader reports them as a damaged manifest, naming it. Not thread-safe; a store that is
// written from several threads locks around it.
#include "core/Error.h"
#include "post/ManifestJson.h"

#include <algorithm>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

template <class Entry>
class ResultList {
public:
    //! The list in the manifest at `path`, or an empty one when there is no file.
    //! Error(CacheCorrupt) naming `path` when it is damaged or of another format.
    static ResultList open(std::string path, std::string format, int version) {
        ResultList list(std::move(path), std::move(format), version);
        const std::optional<nlohmann::json> json =
            readManifestJson(list.path_, list.format_, version);
        if (!json)
            return list;
        list.settings_ = json->value("settings", nlohmann::json::object());
        for (const nlohmann::json& entry : json->value("frames", nlohmann::json::array()))
            list.entries_.push_back(list.entryFrom(entry));
        std::sort(list.entries_.begin(), list.entries_.end(),
                  [](const Entry& a, const Entry& b) { return a.frame < b.frame; });
        return list;
    }

    //! open(), or an empty list when the file is damaged (then `damage` says how): the results it
    //! listed are made again, and the first write replaces the file. For the writers (post),
    //! which would otherwise be stuck behind a file only they can remake.
    static ResultList openOrEmpty(std::string path, std::string format, int version,
                                  std::string& damage) {
        try {
            return open(path, format, version);
        } catch (const Error& error) {
            if (error.kind() != ErrorKind::CacheCorrupt)
                throw;
            damage = error.what();
            return ResultList(std::move(path), std::move(format), version);
        }
    }

    //! Adopts `settings`; when they differ, every entry is unlisted, in the file too.
    void useSettings(const nlohmann::json& settings) {
        if (settings == settings_)
            return;
        settings_ = settings;
        entries_.clear();
        if (std::filesystem::exists(path_))
            write();
    }
    const nlohmann::json& settings() const { return settings_; }

    //! The entry of `frame`, or null.
    const Entry* find(int frame) const {
        const auto at = lowerBound(frame);
        return at != entries_.end() && at->frame == frame ? &*at : nullptr;
    }
    std::vector<int> frames() const {
        std::vector<int> listed;
        for (const Entry& entry : entries_)
            listed.push_back(entry.frame);
        return listed;
    }

    //! Lists `entry` (replacing its frame's) and rewrites the manifest atomically.
    void put(const Entry& entry) {
        const auto at = lowerBound(entry.frame);
        if (at != entries_.end() && at->frame == entry.frame)
            entries_[std::size_t(at - entries_.begin())] = entry;
        else
            entries_.insert(at, entry);
        write();
    }

    const std::string& path() const { return path_; }

    //! From now on the list is written to `path` instead (nothing is written yet): a post run
    //! that writes only its own frames keeps its list apart from the shared one.
    void moveTo(std::string path) { path_ = std::move(path); }

    //! Every entry, sorted by frame.
    const std::vector<Entry>& entries() const { return entries_; }

private:
    ResultList(std::string path, std::string format, int version)
        : path_(std::move(path)), format_(std::move(format)), version_(version) {}

    typename std::vector<Entry>::const_iterator lowerBound(int frame) const {
        return std::lower_bound(
            entries_.begin(), entries_.end(), frame,
            [](const Entry& entry, int wanted) { return entry.frame < wanted; });
    }

    Entry entryFrom(const nlohmann::json& json) const {
        Entry entry;
        try {
            entry = Entry::fromJson(json);
        } catch (const nlohmann::json::exception& error) {
            throw Error(ErrorKind::CacheCorrupt, path_ + ": a frame entry: " + error.what());
        }
        if (entry.frame < 1)
            throw Error(ErrorKind::CacheCorrupt, path_ + ": frame " + std::to_string(entry.frame));
        return entry;
    }

    void write() const {
        nlohmann::json frames = nlohmann::json::array();
        for (const Entry& entry : entries_)
            frames.push_back(entry.toJson());
        writeManifestJson(path_, format_, version_, settings_, frames);
    }

    std::string path_;
    std::string format_;
    int version_;
    nlohmann::json settings_ = nlohmann::json::object();
    std::vector<Entry> entries_; //!< sorted by frame
};

} // namespace airtrap
