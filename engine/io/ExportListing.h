#pragma once
// `export.json` beside the exported sequences (docs/CLI.md "export"): what an importer needs to
// load them without guessing (the Blender add-on reads it): the scene's name, fps and frame
// range, the units, the container's box, and for each sequence its file pattern, the frames
// present, its up axis and each file's CRC-32 (an importer checks a file before handing it to a
// reader that would crash on a damaged one, as Blender's OpenVDB does).
// Every export run adds or replaces the sequences it wrote, so obj, vdb and ply runs into one
// folder share one listing. It holds no time stamp: the same exports give the same bytes, but
// for the checksums of volumes (OpenVDB writes a UUID it draws at random into every file).
#include "core/UpAxis.h"
#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap {

class ExportListing {
public:
    static constexpr const char* kFileName = "export.json";
    static constexpr const char* kFormatName = "airtrap-export";
    static constexpr int kVersion = 1;

    //! The listing in `outDir`. A missing one, or one that is damaged, foreign or of another
    //! version, reads as empty: it only describes files, which the next write lists again.
    static ExportListing readOrEmpty(const std::string& outDir);

    //! The scene the sequences come from: its name, fps and frame range, and its container's
    //! box in the axes `up` (an importer frames its camera and puts its floor by it).
    void setScene(const Scene& scene, UpAxis up);
    //! Records files one run wrote ("water_0001.obj", as ExportReport::files names them), in
    //! the export's axes. A sequence exported again with the same axes gains the frames; with
    //! other axes, the frames of the earlier orientation are dropped from the listing.
    void addFiles(const std::vector<std::string>& names, UpAxis up);
    //! Records the CRC-32 of each of `names` (listed by addFiles) as it is now in `outDir`.
    //! Throws Error(Io) naming a file that cannot be read.
    void recordChecksums(const std::string& outDir, const std::vector<std::string>& names);
    //! Writes `outDir`/export.json atomically.
    void write(const std::string& outDir) const;

    const nlohmann::json& json() const { return json_; }

private:
    nlohmann::json json_ = nlohmann::json::object();
};

} // namespace airtrap
