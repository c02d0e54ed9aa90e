#pragma once
// The start and the end of one parallel loop, told to ThreadSanitizer. oneTBB hands a loop's tasks
// to its workers and waits for them through atomics inside libtbb.so, which Debian builds without
// TSan: a TSan build sees no order between the code before a loop, the loop's bodies and the code
// after it, and would report every loop as a race (docs/TESTING.md "Sanitizers"). In other builds
// each member is empty and compiles away.
#if defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define AIRTRAP_THREAD_SANITIZER 1
#endif
#endif
#if defined(__SANITIZE_THREAD__) && !defined(AIRTRAP_THREAD_SANITIZER)
#define AIRTRAP_THREAD_SANITIZER 1
#endif

#ifdef AIRTRAP_THREAD_SANITIZER
#include <sanitizer/tsan_interface.h>
#endif

namespace airtrap {

//! Kept by the thread that starts a loop. Two tokens, not one, so that the tasks are ordered
//! after the start and the end after the tasks, but not one task after another: a race between
//! two bodies stays visible.
class ForkJoin {
public:
    ForkJoin() = default;
    ForkJoin(const ForkJoin&) = delete;
    ForkJoin& operator=(const ForkJoin&) = delete;

    //! The starter, when everything the tasks read is written (the task functions included:
    //! TBB may run them by reference), just before the loop starts.
    void loopStarts() { release(&forked_); }
    //! A task sees everything its loop's starter did before the loop.
    void taskStarts() { acquire(&forked_); }
    //! The loop's end sees everything a finished task did.
    void taskEnds() { release(&joined_); }
    //! A reduction that merges two tasks' values sees what both did.
    void mergeStarts() { acquire(&joined_); }
    //! The starter, after the loop returned.
    void loopEnded() { acquire(&joined_); }

private:
#ifdef AIRTRAP_THREAD_SANITIZER
    static void release(char* token) {
        __tsan_release(token);
    }
    static void acquire(char* token) {
        __tsan_acquire(token);
    }
#else
    static void release(char*) {}
    static void acquire(char*) {}
#endif

    char forked_ = 0;
    char joined_ = 0;
};

} // namespace airtrap
