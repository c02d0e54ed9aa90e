#include "io/ExportListing.h"

#include "cache/FrameFile.h"
#include "core/AtomicFile.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <map>
#include <optional>
#include <set>

namespace airtrap {

namespace {

//! "water_0001.obj" → sequence "water.obj", frame 1, pattern "water_####.obj"; nothing for a
//! name that is not a frame of a sequence.
struct SequenceFile {
    std::string sequence;
    std::string pattern;
    int frame = 0;
};

std::optional<SequenceFile> sequenceFileOf(const std::string& name) {
    const std::size_t dot = name.rfind('.');
    const std::size_t underscore = name.rfind('_', dot);
    if (dot == std::string::npos || underscore == std::string::npos || dot - underscore < 5)
        return std::nullopt;
    const std::string digits = name.substr(underscore + 1, dot - underscore - 1);
    if (!std::all_of(digits.begin(), digits.end(), [](unsigned char c) { return std::isdigit(c); }))
        return std::nullopt;
    const std::string stem = name.substr(0, underscore);
    const std::string ext = name.substr(dot + 1);
    return SequenceFile{stem + "." + ext, stem + "_####." + ext, std::stoi(digits)};
}

} // namespace

ExportListing ExportListing::readOrEmpty(const std::string& outDir) {
    ExportListing listing;
    const std::string path = outDir + "/" + kFileName;
    if (!std::filesystem::is_regular_file(path))
        return listing;
    try {
        const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
        nlohmann::json json = nlohmann::json::parse(bytes.begin(), bytes.end());
        if (json.is_object() && json.value("format", "") == kFormatName &&
            json.value("version", 0) == kVersion && json["sequences"].is_object())
            listing.json_ = std::move(json);
    } catch (const std::exception&) {
        // Damaged or unreadable: it is rewritten from what this run writes.
    }
    return listing;
}

void ExportListing::setScene(const Scene& scene, UpAxis up) {
    json_["format"] = kFormatName;
    json_["version"] = kVersion;
    json_["scene"] = scene.name;
    json_["units"] = "m";
    json_["fps"] = scene.frames.fps;
    json_["frame_start"] = 1;
    json_["frame_end"] = scene.frames.endFrame;
    // The turn to z up swaps and negates an axis, so the corners are sorted again.
    const Vec3d a = toExportAxes(scene.container.min, up);
    const Vec3d b = toExportAxes(scene.container.max, up);
    // Adding +0 turns the −0 a negated axis gives into 0, which reads better in the file.
    const Vec3d low = a.cwiseMin(b) + Vec3d::Zero();
    const Vec3d high = a.cwiseMax(b) + Vec3d::Zero();
    json_["container"] = {{"min", {low.x(), low.y(), low.z()}},
                          {"max", {high.x(), high.y(), high.z()}},
                          {"up_axis", std::string(upAxisName(up))}};
    if (!json_.contains("sequences") || !json_["sequences"].is_object())
        json_["sequences"] = nlohmann::json::object();
}

void ExportListing::addFiles(const std::vector<std::string>& names, UpAxis up) {
    nlohmann::json& sequences = json_["sequences"];
    if (!sequences.is_object())
        sequences = nlohmann::json::object();
    const std::string axis(upAxisName(up));
    std::map<std::string, std::set<int>> added;
    std::map<std::string, std::string> patterns;
    for (const std::string& name : names)
        if (const std::optional<SequenceFile> file = sequenceFileOf(name)) {
            added[file->sequence].insert(file->frame);
            patterns[file->sequence] = file->pattern;
        }
    for (const auto& [sequence, frames] : added) {
        nlohmann::json& entry = sequences[sequence];
        std::set<int> all = frames;
        nlohmann::json checksums = nlohmann::json::object();
        if (entry.is_object() && entry.value("up_axis", "") == axis && entry["frames"].is_array())
            for (const nlohmann::json& frame : entry["frames"])
                if (frame.is_number_integer())
                    all.insert(frame.get<int>());
        if (entry.is_object() && entry.value("up_axis", "") == axis && entry["crc32"].is_object())
            for (const auto& [frame, crc] : entry["crc32"].items())
                // A frame written again is checked again (recordChecksums).
                if (crc.is_number_unsigned() && !frames.count(std::atoi(frame.c_str())))
                    checksums[frame] = crc;
        entry = {{"pattern", patterns[sequence]},
                 {"up_axis", axis},
                 {"frames", std::vector<int>(all.begin(), all.end())},
                 {"crc32", checksums}};
    }
}

void ExportListing::recordChecksums(const std::string& outDir,
                                    const std::vector<std::string>& names) {
    nlohmann::json& sequences = json_["sequences"];
    for (const std::string& name : names) {
        const std::optional<SequenceFile> file = sequenceFileOf(name);
        if (!file || !sequences.contains(file->sequence))
            continue;
        const std::vector<std::uint8_t> bytes = AtomicFile::read(outDir + "/" + name);
        sequences[file->sequence]["crc32"][std::to_string(file->frame)] =
            computeCrc32(bytes.data(), bytes.size());
    }
}

void ExportListing::write(const std::string& outDir) const {
    AtomicFile::write(outDir + "/" + kFileName, json_.dump(2) + "\n");
}

} // namespace airtrap
