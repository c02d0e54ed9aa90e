#pragma once
// `airtrap-cli info DIR --bubbles`: where the bake's trapped bubbles lived, a row per frame and the
// totals (BubbleCensus; the rule in docs/VALIDATION.md), as a table or one JSON object.
#include "cache/FrameCache.h"
#include "post/BubbleCensus.h"

#include <nlohmann/json.hpp>
#include <ostream>

namespace airtrap::cli {

class BubbleCensusReport {
public:
    //! Surveys every intact frame of `cache` in order; damaged frames are named on `notes` and
    //! skipped.
    BubbleCensusReport(const FrameCache& cache, std::ostream& notes);

    nlohmann::ordered_json toJson() const;
    void printText(std::ostream& out) const;

    const BubbleCensus& census() const { return census_; }

private:
    //! Mean bubbles in water per frame over frames last / 2 + 1 to last.
    double inWaterSecondHalf() const;

    BubbleCensus census_;
};

} // namespace airtrap::cli
