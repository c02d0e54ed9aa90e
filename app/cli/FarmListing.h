#pragma once
// DIR/wedges.json (docs/FARM.md "wedges.json"): what a farm submission holds — the scene, each
// wedge's values and folder, and each job with its script and scheduler id. `farm status` and
// `farm cancel` read it; a second `farm submit` into the same folder compares against it.
#include "FarmJob.h"
#include "FarmWedge.h"

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace airtrap::cli {

struct FarmListing {
    static constexpr const char* kFormatName = "airtrap-farm";
    static constexpr int kVersion = 1;

    std::string scene;                  //!< absolute path
    std::vector<std::string> overrides; //!< `--set` for every wedge
    std::vector<FarmWedge> wedges;
    //! Jobs over every wedge, after all of theirs (the contact sheet).
    std::vector<FarmJob> finalJobs;

    nlohmann::json toJson() const;
    //! Error(InvalidInput) naming `path` when it is not a farm listing this build reads.
    static FarmListing read(const std::string& path);
    void write(const std::string& path) const;

    //! True when `other` bakes the same scene with the same values into the same folders.
    bool sameBakes(const FarmListing& other) const;
    //! Every job id, arrays by their array id.
    std::vector<std::string> jobIds() const;
};

} // namespace airtrap::cli
