#pragma once
#include <memory>

namespace airtrap {

//! Caps the worker threads of every parallel loop while it lives (0 = all cores).
class ThreadLimit {
public:
    explicit ThreadLimit(int threads);
    ~ThreadLimit();
    ThreadLimit(const ThreadLimit&) = delete;
    ThreadLimit& operator=(const ThreadLimit&) = delete;

    //! Threads actually in use.
    int threads() const { return threads_; }

private:
    struct Control;
    std::unique_ptr<Control> control_;
    int threads_ = 0;
};

} // namespace airtrap
