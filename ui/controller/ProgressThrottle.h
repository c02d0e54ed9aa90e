#pragma once
// Thins out progress reports: a small scene takes thousands of steps a second, and one queued
// signal per step would flood the editor's event loop for no visible gain.
#include <chrono>
#include <optional>

namespace airtrap {

class ProgressThrottle {
public:
    //! The clock reports are timed with.
    using Clock = std::chrono::steady_clock;

    //! Lets at most one report through per `interval`.
    explicit ProgressThrottle(Clock::duration interval) : interval_(interval) {}

    //! True when a report made at `now` should be delivered; remembers it as the last one.
    bool admit(Clock::time_point now);

private:
    Clock::duration interval_;
    std::optional<Clock::time_point> lastDelivery_;
};

} // namespace airtrap
