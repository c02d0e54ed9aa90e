#include "controller/BakeProgressMeter.h"

#include "bake/BakeProgress.h"

#include <algorithm>

namespace airtrap {

namespace {

//! An ETA from the first second or the first half per cent of a range swings wildly (the first
//! steps include the neighbour grid's set-up); the field shows "…" until both have passed.
constexpr double kMinimumSecondsForEta = 1.0;
constexpr double kMinimumShareForEta = 0.005;

} // namespace

void BakeProgressMeter::start(double now) {
    *this = BakeProgressMeter{};
    startedAt_ = now;
}

double BakeProgressMeter::update(const BakeProgress& progress) {
    const double share = shareOfRange(progress);
    // A resumed bake starts part-way: its rate is measured from where it began.
    if (fractionAtStart_ < 0.0)
        fractionAtStart_ = share;
    fraction_ = std::max(fraction_, share);
    frame_ = progress.frame;
    lastFrame_ = progress.lastFrame;
    return fraction_;
}

void BakeProgressMeter::pause(double now) {
    if (!isPaused())
        pausedAt_ = now;
}

void BakeProgressMeter::resume(double now) {
    if (!isPaused())
        return;
    pausedSeconds_ += now - pausedAt_;
    pausedAt_ = -1.0;
}

double BakeProgressMeter::etaSeconds(double now) const {
    const double active = activeSeconds(now);
    const double done = fraction_ - std::max(fractionAtStart_, 0.0);
    if (active < kMinimumSecondsForEta || done < kMinimumShareForEta)
        return -1.0;
    return active / done * (1.0 - fraction_);
}

double BakeProgressMeter::activeSeconds(double now) const {
    const double end = isPaused() ? pausedAt_ : now;
    return end - startedAt_ - pausedSeconds_;
}

double BakeProgressMeter::shareOfRange(const BakeProgress& progress) {
    // Frame 1 is the initial state, written before the first step: the range to compute is
    // frames 2..last, and frame f at fraction s has (f - 2 + s) of its (last - 1) frames done.
    const int framesToCompute = progress.lastFrame - 1;
    if (framesToCompute <= 0)
        return 1.0;
    const double done = progress.frame - 2 + std::clamp(progress.frameFraction, 0.0, 1.0);
    return std::clamp(done / framesToCompute, 0.0, 1.0);
}

} // namespace airtrap
