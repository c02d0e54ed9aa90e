#include "controller/PauseGate.h"

namespace airtrap {

void PauseGate::close() {
    const std::lock_guard lock(mutex_);
    closed_ = !released_;
}

void PauseGate::open() {
    {
        const std::lock_guard lock(mutex_);
        closed_ = false;
    }
    opened_.notify_all();
}

void PauseGate::release() {
    {
        const std::lock_guard lock(mutex_);
        released_ = true;
        closed_ = false;
    }
    opened_.notify_all();
}

void PauseGate::pass() {
    std::unique_lock lock(mutex_);
    opened_.wait(lock, [this] { return !closed_; });
}

} // namespace airtrap
