#pragma once
#include <atomic>
#include <functional>
#include <string>

namespace airtrap {

//! One object for both cancellation and progress, passed to every long operation (steps, bake,
//! post, export). Shaped like OpenVDB's util::NullInterrupter so it can be handed to its tools.
class Interrupter {
public:
    using ProgressCallback = std::function<void(const std::string& stage, double percent)>;

    Interrupter() = default;
    explicit Interrupter(ProgressCallback onProgress) : onProgress_(std::move(onProgress)) {}
    //! One part of a parallel operation: it stops when `parent` is asked to, and keeps its own
    //! stage and progress, so parts running at once do not write over each other's (or the
    //! parent's) progress. `parent` must outlive it.
    explicit Interrupter(const Interrupter* parent) : parent_(parent) {}

    //! Asks the running operation to stop at its next safe point. Thread-safe.
    void requestStop() { stopRequested_.store(true, std::memory_order_relaxed); }
    void reset() { stopRequested_.store(false, std::memory_order_relaxed); }
    bool stopRequested() const {
        return stopRequested_.load(std::memory_order_relaxed) ||
               (parent_ != nullptr && parent_->stopRequested());
    }

    void start(const std::string& stage) { stage_ = stage; }
    void end() {}
    //! Reports progress (0–100, or negative when unknown) and answers whether to stop.
    bool wasInterrupted(double percent = -1.0) {
        if (onProgress_ && percent >= 0.0)
            onProgress_(stage_, percent);
        return stopRequested();
    }

private:
    std::atomic<bool> stopRequested_{false};
    const Interrupter* parent_ = nullptr;
    ProgressCallback onProgress_;
    std::string stage_;
};

} // namespace airtrap
