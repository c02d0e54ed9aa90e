#pragma once
// The largest of f(i) over a range, in parallel. max is exact in any order, so the result does not
// depend on the number of threads or on how the range was split.
#include "core/Parallel.h"

#include <algorithm>
#include <cstddef>
#include <tbb/blocked_range.h>

namespace airtrap {

template <class F>
double parallelMax(std::size_t n, F&& f, std::size_t grain = 1024) {
    // Not "Range": in a unity batch a .cpp's own Range alias would be shadowed (clang -Wshadow).
    using MaxRange = tbb::blocked_range<std::size_t>;
    return parallelReduce(
        MaxRange(0, n, grain), 0.0,
        [&](const MaxRange& r, double best) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
                best = std::max(best, static_cast<double>(f(i)));
            return best;
        },
        [](double a, double b) { return std::max(a, b); });
}

} // namespace airtrap
