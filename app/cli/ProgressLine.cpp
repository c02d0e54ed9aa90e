#include "ProgressLine.h"

#include <cmath>
#include <cstdio>

namespace airtrap::cli {

namespace {

constexpr auto kMinRedraw = std::chrono::milliseconds(100);

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

//! `counts`: what the frame holds ("25000 particles", "25000 particles  3 bubbles").
std::string line(int frame, int lastFrame, double time, double stepsPerSecond,
                 const std::string& counts, const std::string& eta) {
    return "frame " + std::to_string(frame) + "/" + std::to_string(lastFrame) +
           "  t=" + format("%.3f", time) + " s  " + format("%.0f", stepsPerSecond) + " steps/s  " +
           counts + "  ETA " + eta;
}

} // namespace

ProgressLine::ProgressLine(std::ostream& out, Mode mode, double fps, int lastFrame,
                           bool showBubbles)
    : out_(out), mode_(mode), fps_(fps), lastFrame_(lastFrame), showBubbles_(showBubbles) {}

std::string ProgressLine::counts() const {
    std::string text = std::to_string(particles_) + " particles";
    if (showBubbles_)
        text += "  " + std::to_string(bubbles_) + " bubbles";
    return text;
}

std::string ProgressLine::clock(double seconds) {
    if (seconds < 0.0 || !std::isfinite(seconds))
        return "--:--:--";
    const long total = std::lround(seconds);
    char text[32];
    std::snprintf(text, sizeof text, "%ld:%02ld:%02ld", total / 3600, total / 60 % 60, total % 60);
    return text;
}

double ProgressLine::eta(int frame, double frameFraction) const {
    const double done = framesSimulated_ + frameFraction;
    if (done <= 0.05)
        return -1.0;
    const double elapsed = std::chrono::duration<double>(Clock::now() - start_).count();
    const double remaining = (lastFrame_ - frame) + (1.0 - frameFraction);
    return elapsed / done * remaining;
}

void ProgressLine::step(const BakeProgress& progress) {
    particles_ = progress.particles;
    bubbles_ = progress.bubbles;
    if (mode_ != Mode::InPlace)
        return;
    const auto now = Clock::now();
    if (now - lastShown_ < kMinRedraw)
        return;
    lastShown_ = now;
    show(line(progress.frame, lastFrame_, progress.simTime, progress.stepsPerSecond, counts(),
              clock(eta(progress.frame, progress.frameFraction))));
}

void ProgressLine::frameDone(int frame, const FrameStats& stats) {
    if (framesDone_++ == 0)
        firstFrameDone_ = frame;
    lastFrameDone_ = frame;
    steps_ += stats.stepsInFrame;
    stepSeconds_ += stats.wallSeconds;
    if (stats.stepsInFrame > 0)
        ++framesSimulated_;
    // Bubbles are created and deleted during the steps: the last step's count is the frame's.
    const double time = (frame - 1) / fps_;
    if (mode_ == Mode::Silent)
        return;
    if (stats.stepsInFrame == 0) {
        // Frame 1 of a fresh bake: the initial state, nothing simulated yet.
        note("frame " + std::to_string(frame) + "/" + std::to_string(lastFrame_) +
             "  t=" + format("%.3f", time) + " s  initial state");
        return;
    }
    const double stepsPerSecond =
        stats.wallSeconds > 0.0 ? stats.stepsInFrame / stats.wallSeconds : 0.0;
    const std::string text =
        line(frame, lastFrame_, time, stepsPerSecond, counts(), clock(eta(frame, 1.0)));
    if (mode_ == Mode::PerFrame) {
        out_ << text << '\n' << std::flush;
        return;
    }
    // Fast frames would redraw faster than anyone reads; the last frame is always shown.
    const auto now = Clock::now();
    if (now - lastShown_ < kMinRedraw && frame != lastFrame_)
        return;
    lastShown_ = now;
    show(text);
}

void ProgressLine::note(const std::string& message) {
    finish();
    out_ << message << '\n' << std::flush;
}

void ProgressLine::finish() {
    if (shownWidth_ == 0)
        return;
    out_ << '\n' << std::flush;
    shownWidth_ = 0;
}

void ProgressLine::show(const std::string& text) {
    // Pad with spaces over the tail of a longer previous line.
    const std::size_t pad = shownWidth_ > text.size() ? shownWidth_ - text.size() : 0;
    out_ << '\r' << text << std::string(pad, ' ') << std::flush;
    shownWidth_ = text.size();
}

} // namespace airtrap::cli
