// The thread sanitizer build's own check (docs/TESTING.md "Sanitizers"): two tasks of one of our
// parallel loops write the same variable without any order between them, and TSan must say so.
// It shows that the suppressions (tests/sanitizers/tsan.supp), the instrumentation left out of
// oneTBB's headers and the loops' fork/join annotations (core/ForkJoin.h) hide nothing in a loop
// body. ctest passes when the report names this file.
#include "core/Parallel.h"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <tbb/blocked_range.h>
#include <tbb/task_arena.h>
#include <thread>

namespace {

//! Waits, up to a few seconds, until both tasks have started, so that they run on two threads.
//! Relaxed: the counter must not order the two writes that follow.
void meetTheOtherTask(std::atomic<int>& arrived) {
    arrived.fetch_add(1, std::memory_order_relaxed);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(5);
    while (arrived.load(std::memory_order_relaxed) < 2 &&
           std::chrono::steady_clock::now() < deadline)
        std::this_thread::yield();
}

} // namespace

int main() {
    std::atomic<int> arrived{0};
    double shared = 0.0;
    tbb::task_arena twoThreads(2);
    twoThreads.execute([&] {
        airtrap::parallelFor(tbb::blocked_range<int>(0, 2, 1),
                             [&](const tbb::blocked_range<int>& part) {
                                 meetTheOtherTask(arrived);
                                 shared += part.begin() + 1.0;
                             });
    });
    std::printf("%s: %.0f (3 when both tasks ran)\n",
                arrived.load() == 2 ? "two threads" : "one thread only", shared);
    return 0;
}
