#pragma once
// A wedge as a farm submission runs it (FarmListing): its values, cache folder, frames and jobs.
#include "FarmJob.h"
#include "Wedge.h"

#include <string>
#include <vector>

namespace airtrap::cli {

struct FarmWedge {
    Wedge wedge;
    std::string folder; //!< the wedge's cache folder
    int firstFrame = 1;
    int lastFrame = 1;
    std::vector<FarmJob> jobs;
};

} // namespace airtrap::cli
