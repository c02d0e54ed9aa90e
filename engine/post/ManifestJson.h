#pragma once
// The JSON manifests the post stage keeps beside the cache (`post/post.json`,
// `post/subgrid.json`): an object naming its format and version, who wrote it, the settings its
// results were made with, and a list of frames. Reading checks the first two, so a damaged or
// foreign file is reported by name instead of being taken for an empty store.
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace airtrap {

//! The manifest at `path`, or nothing when there is no file. Not JSON, another format or a newer
//! version → Error(CacheCorrupt) naming `path`.
std::optional<nlohmann::json> readManifestJson(const std::string& path, const std::string& format,
                                               int maxVersion);

//! Writes `{format, format_version, creator, settings, frames}` atomically (Error(Io) names it).
void writeManifestJson(const std::string& path, const std::string& format, int version,
                       const nlohmann::json& settings, const nlohmann::json& frames);

//! Creates `dir` and its parents; Error(Io) names it when that fails.
void createResultFolder(const std::string& dir);

} // namespace airtrap
