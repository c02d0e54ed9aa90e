#pragma once
// Two parts of a step that share no data, run at the same time: the short serial stretches of
// one fill the other's gaps instead of keeping a thread waiting. Each part is timed on its own,
// so their phase times overlap.
#include "core/Parallel.h"

#include <utility>

namespace airtrap {

//! Runs `first` and `second` as two tasks and returns when both are done.
template <class First, class Second>
void runBeside(First&& first, Second&& second) {
    parallelInvoke(std::forward<First>(first), std::forward<Second>(second));
}

} // namespace airtrap
