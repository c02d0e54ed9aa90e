#pragma once
// Where the trapped bubbles of a bake live, frame by frame (docs/VALIDATION.md, "Where the
// bubbles live"): each living bubble judged in water, floating or airborne by BubbleImmersion's
// 26-probe rule against the frame's water, its rise speed while in water against the capped
// Stokes speed, the depth at which bubbles are made, how long they live, and whether the books
// balance (made = alive + deleted, by cause). `airtrap-cli info --bubbles` prints it; the tests
// assert its figures on whole bakes.
#include "bubbles/BubbleImmersion.h"
#include "bubbles/BubbleTally.h"
#include "cache/FrameFile.h"
#include "scene/Scene.h"

#include <cstdint>
#include <map>
#include <vector>

namespace airtrap {

struct BubbleCensusFrame {
    int frame = 0;
    double time = 0.0;                 //!< s
    int alive = 0;                     //!< bubbles at the frame's end
    int inWater = 0;                   //!< of them, with at least 13 of 26 probes wet
    int floating = 0;                  //!< 7–12 wet probes: at the free surface
    int airborne = 0;                  //!< fewer than 7 wet probes
    double meanRiseSpeedInWater = 0.0; //!< m/s, vertical speed of the bubbles in water
    //! m/s, the same relative to the water around each (eq. 5's slip; the current carries a
    //! bubble along on top of it)
    double meanSlipSpeedInWater = 0.0;
    double meanTargetRiseSpeed = 0.0; //!< m/s, their capped Stokes speed (eq. 5)
    int created = 0;                  //!< bubbles the frame made
    std::uint64_t deleted = 0;        //!< bubbles the frame deleted, any cause
    bool booksBalance = true;         //!< created so far = alive + deleted so far
};

struct BubbleCensusTotals {
    int frames = 0;
    std::uint64_t bubbleFrames = 0; //!< living bubbles summed over the frames
    std::uint64_t inWater = 0, floating = 0, airborne = 0;
    double meanRiseSpeedInWater = 0.0;    //!< m/s over every in-water bubble-frame
    double meanSlipSpeedInWater = 0.0;    //!< m/s, the same relative to the water around each
    double meanTargetRiseSpeed = 0.0;     //!< m/s, the same bubble-frames' capped Stokes speed
    std::uint64_t created = 0;            //!< bubbles made since t = 0 (by the last frame)
    std::uint64_t alive = 0;              //!< alive at the last frame
    BubbleTally deleted;                  //!< deleted since t = 0, by cause (the last frame's)
    std::uint64_t newBubblesMeasured = 0; //!< bubbles first seen in a frame of the survey
    double meanDepthAtCreation = 0.0;     //!< m of water over their centre when first seen
    //! Of them, how many were in water, floating and airborne when first seen.
    std::uint64_t newInWater = 0, newFloating = 0, newAirborne = 0;
    std::uint64_t ended = 0;   //!< bubbles seen alive, then gone
    double meanLifetime = 0.0; //!< s, their age when last seen
    bool booksBalance = true;  //!< in every frame surveyed

    double inWaterShare() const { return share(inWater); }
    double floatingShare() const { return share(floating); }
    double airborneShare() const { return share(airborne); }
    //! Share of the bubble-frames that `count` of them make.
    double share(std::uint64_t count) const {
        return bubbleFrames == 0 ? 0.0 : double(count) / double(bubbleFrames);
    }
};

class BubbleCensus {
public:
    explicit BubbleCensus(const Scene& scene);

    //! Surveys one frame (frames in ascending order) and adds it to the totals.
    BubbleCensusFrame add(const FrameData& frame);

    const std::vector<BubbleCensusFrame>& frames() const { return frames_; }
    const BubbleCensusTotals& totals() const { return totals_; }
    //! Mean bubbles in water per frame over the surveyed frames numbered `firstFrame` and later
    //! (the report gives it for the second half of the bake).
    double meanInWaterFrom(int firstFrame) const;

private:
    //! m of continuous water over `centre`: probes a spacing apart up its vertical, from the
    //! bubble's top, until one finds no water within a spacing.
    double waterDepthOver(const Vec3d& centre, double radius, const NeighborGrid& grid,
                          const PositionArrays& positions) const;
    double targetRiseSpeed(double radius) const;
    //! m/s, `bubble`'s vertical speed relative to the water around it.
    static double slipSpeed(const BubbleState& bubble, const Vec3d& up);

    Scene scene_;
    BubbleImmersion immersion_;
    std::vector<BubbleCensusFrame> frames_;
    BubbleCensusTotals totals_;
    std::map<std::uint32_t, double> lastAge_; //!< age of each bubble in the frame before
    double depthSum_ = 0.0, lifetimeSum_ = 0.0, riseSum_ = 0.0, slipSum_ = 0.0, targetSum_ = 0.0;
};

} // namespace airtrap
