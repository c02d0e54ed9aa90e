#pragma once
// The whole bake's progress as the status bar shows it: the share of the frame range done (the
// frames finished, plus the current frame's share as the finer part), an ETA from the time the
// bake actually ran (pauses left out), and whether it is paused. Reports arrive per step from the
// bake thread; the share never goes back, so a bar fed with it never jumps back between frames.
// Times are given in seconds by the caller, so the meter is tested without waiting.
namespace airtrap {

struct BakeProgress;

class BakeProgressMeter {
public:
    //! A new bake (or a resumed one) starts at `now`.
    void start(double now);
    //! Takes a step's report; returns the share of the range done, 0–1. Reports queued before a
    //! pause may arrive after it: they count, and the meter stays paused.
    double update(const BakeProgress& progress);
    void pause(double now);
    void resume(double now);

    bool isPaused() const { return pausedAt_ >= 0.0; }
    //! 0–1 of the frame range: frame 1 is the scene's start, the last frame its end.
    double fraction() const { return fraction_; }
    //! Seconds until the bake ends at the rate it has run at so far; negative until it has run
    //! for long enough to say.
    double etaSeconds(double now) const;
    //! The frame being computed and the last one, from the latest report (0 before one came).
    int frame() const { return frame_; }
    int lastFrame() const { return lastFrame_; }

private:
    double activeSeconds(double now) const;
    static double shareOfRange(const BakeProgress& progress);

    double startedAt_ = 0.0;
    double pausedSeconds_ = 0.0;
    double pausedAt_ = -1.0;
    double fractionAtStart_ = -1.0;
    double fraction_ = 0.0;
    int frame_ = 0;
    int lastFrame_ = 0;
};

} // namespace airtrap
