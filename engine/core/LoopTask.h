#pragma once
// The function a parallel loop hands to oneTBB: the loop's body, bracketed by its ForkJoin. TBB
// runs it by reference or copies it, on any thread, with an order TSan cannot see
// (core/ForkJoin.h); so its own fields are only ever read and written as atomics, with release
// and acquire: reading them comes before the ForkJoin's order is known, and must already see
// what the thread that wrote them did before (its stack memory, where TBB may keep the task, is
// reused). On x86 and ARMv8 such loads and stores cost no more than plain ones.
#include "core/ForkJoin.h"

#include <atomic>
#include <type_traits>
#include <utility>

namespace airtrap {

//! `Merges`: the reduction that merges two tasks' values, which sees what both did.
template <class Body, bool Merges = false>
class LoopTask {
public:
    LoopTask(ForkJoin& loop, const Body& body) { set(&loop, &body); }
    LoopTask(const LoopTask& other) { set(other.loopPointer(), other.bodyPointer()); }
    LoopTask& operator=(const LoopTask&) = delete;

    template <class... Args>
    decltype(auto) operator()(Args&&... args) const {
        ForkJoin& loop = *loopPointer();
        if constexpr (Merges)
            loop.mergeStarts();
        else
            loop.taskStarts();
        const Body& body = *bodyPointer();
        if constexpr (std::is_void_v<std::invoke_result_t<const Body&, Args&&...>>) {
            body(std::forward<Args>(args)...);
            loop.taskEnds();
        } else {
            auto result = body(std::forward<Args>(args)...);
            loop.taskEnds();
            return result;
        }
    }

private:
    // std::atomic's constructor would write its value as plain memory: atomic_ref never does.
    void set(ForkJoin* loop, const Body* body) {
        std::atomic_ref(loop_).store(loop, std::memory_order_release);
        std::atomic_ref(body_).store(body, std::memory_order_release);
    }
    ForkJoin* loopPointer() const { return std::atomic_ref(loop_).load(std::memory_order_acquire); }
    const Body* bodyPointer() const {
        return std::atomic_ref(body_).load(std::memory_order_acquire);
    }

    // mutable: atomic_ref needs a non-const object even to load.
    mutable ForkJoin* loop_;
    mutable const Body* body_;
};

} // namespace airtrap
