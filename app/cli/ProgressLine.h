#pragma once
// The bake's progress line: frame, sim time, steps/s, particles, bubbles (when the scene simulates
// them), ETA. On a terminal one line is rewritten in place after every step (at most 10 times a
// second); into a pipe or a log file it is one line per finished frame, so logs stay readable.
#include "bake/Baker.h"
#include "sim/FrameStats.h"

#include <chrono>
#include <cstddef>
#include <ostream>
#include <string>

namespace airtrap::cli {

class ProgressLine {
public:
    enum class Mode {
        InPlace,  //!< one line rewritten with '\r' (a terminal)
        PerFrame, //!< one line per finished frame (a pipe, a log file)
        Silent,   //!< counts frames for the summary, prints nothing (--quiet)
    };

    //! `fps` turns frame numbers into time; `lastFrame` is the bake's last frame; `showBubbles`
    //! adds the count of alive bubbles (for scenes with bubbles enabled).
    ProgressLine(std::ostream& out, Mode mode, double fps, int lastFrame, bool showBubbles);

    //! After every step (Baker::onProgress).
    void step(const BakeProgress& progress);
    //! After a frame is on disk (Baker::onFrame).
    void frameDone(int frame, const FrameStats& stats);
    //! Prints a message on its own line without mangling the in-place line (even when Silent:
    //! notes are not progress).
    void note(const std::string& message);
    //! Ends the in-place line, before the final summary or an error.
    void finish();

    //! Frames finished since construction (frame 1 of a fresh bake included).
    int framesDone() const { return framesDone_; }
    //! The first and the last frame finished since construction (0 when none).
    int firstFrameDone() const { return firstFrameDone_; }
    int lastFrameDone() const { return lastFrameDone_; }
    //! Sum of the steps and of their wall time over the finished frames.
    std::uint64_t steps() const { return steps_; }
    double stepSeconds() const { return stepSeconds_; }

    //! "0:01:23"; "--:--:--" for a negative (unknown) time.
    static std::string clock(double seconds);

private:
    using Clock = std::chrono::steady_clock;

    //! Seconds to the end, from the wall time per frame so far; negative while unknown.
    double eta(int frame, double frameFraction) const;
    //! "25000 particles", and "  3 bubbles" after it when they are shown.
    std::string counts() const;
    void show(const std::string& line);

    std::ostream& out_;
    Mode mode_;
    double fps_;
    Clock::time_point start_ = Clock::now();
    Clock::time_point lastShown_{};
    std::size_t shownWidth_ = 0;
    int lastFrame_;
    int firstFrameDone_ = 0;
    int lastFrameDone_ = 0;
    int framesDone_ = 0;
    //! Frames actually simulated (not the initial frame 1), the basis of the ETA.
    int framesSimulated_ = 0;
    bool showBubbles_;
    std::size_t particles_ = 0;
    std::size_t bubbles_ = 0; //!< alive at the last step or frame end
    std::uint64_t steps_ = 0;
    double stepSeconds_ = 0.0;
};

} // namespace airtrap::cli
