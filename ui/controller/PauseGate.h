#pragma once
// Where a paused bake waits. The bake thread passes through the gate after every step; while the
// gate is closed it sleeps there, in the middle of a frame, so resuming continues the very same
// bake with nothing lost or recomputed.
#include <condition_variable>
#include <mutex>

namespace airtrap {

class PauseGate {
public:
    //! Closes the gate: the next pass blocks. Thread-safe.
    void close();
    //! Opens the gate and wakes a waiting pass. Thread-safe.
    void open();
    //! Opens the gate for good (a stopping bake must not wait for a resume that never comes).
    void release();
    //! Returns at once while the gate is open, else blocks until open() or release().
    void pass();

private:
    std::mutex mutex_;
    std::condition_variable opened_;
    bool closed_ = false;
    bool released_ = false;
};

} // namespace airtrap
