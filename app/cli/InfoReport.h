#pragma once
// What `info` says about one cached frame: the JSON object of docs/CLI.md "info" (with the fields
// that exist in this version; fields are added, never renamed) and a short text for people.
#include "cache/CacheManifest.h"
#include "cache/FrameFile.h"

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>

namespace airtrap::cli {

class InfoReport {
public:
    InfoReport(const FrameData& frame, const CacheManifest& manifest, std::string directory);

    //! `frame`, `time`, `steps`, `fluid`, `bodies`, `bubbles`, `timing`, `pressure_solve` (DFSPH
    //! frames only), `cache`.
    nlohmann::ordered_json toJson() const;
    //! A few lines for a terminal.
    void printText(std::ostream& out) const;

private:
    nlohmann::ordered_json fluidJson() const;
    nlohmann::ordered_json bodiesJson() const;
    //! Alive bubbles with their totals since frame 1 and this frame's creations and deletions.
    nlohmann::ordered_json bubblesJson() const;
    nlohmann::ordered_json timingJson() const;
    //! The frame's DFSPH solves: steps, iterations per step, density error, unconverged steps.
    nlohmann::ordered_json pressureSolveJson() const;
    nlohmann::ordered_json cacheJson() const;

    const FrameData& frame_;
    const CacheManifest& manifest_;
    std::string directory_;
};

} // namespace airtrap::cli
