#pragma once
// Sums over a range in parallel that give the same bits on any number of threads: the range is
// split at fixed points and the parts are added in the same order every time.
#include "core/Parallel.h"

#include <cstddef>
#include <tbb/blocked_range.h>

namespace airtrap {

//! `zero` + Σ f(i) over [0, n), split every `grain` indices. T is a double or a fixed-size
//! vector of them (several sums in one pass).
template <class T, class F>
T deterministicSum(std::size_t n, std::size_t grain, const T& zero, F&& f) {
    // Not "Range": in a unity batch a .cpp's own Range alias would be shadowed (clang -Wshadow).
    using SumRange = tbb::blocked_range<std::size_t>;
    return parallelDeterministicReduce(
        SumRange(0, n, grain), zero,
        [&](const SumRange& r, T sum) {
            for (std::size_t i = r.begin(); i != r.end(); ++i)
                sum += f(i);
            return sum;
        },
        [](const T& a, const T& b) { return T(a + b); });
}

} // namespace airtrap
