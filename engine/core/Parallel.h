#pragma once
// The engine's parallel loops: oneTBB's algorithms, unchanged in how they split and order the
// work (so results keep their bits), with each loop's start and end made visible to
// ThreadSanitizer (core/ForkJoin.h). Engine code calls these, never tbb:: algorithms directly.
#include "core/ForkJoin.h"
#include "core/LoopTask.h"

#include <tbb/parallel_for.h>
#include <tbb/parallel_invoke.h>
#include <tbb/parallel_reduce.h>

namespace airtrap {

//! tbb::parallel_for(range, body): body(part) for parts of the range.
template <class Range, class Body>
void parallelFor(const Range& range, const Body& body) {
    ForkJoin loop;
    const LoopTask<Body> task(loop, body);
    loop.loopStarts();
    tbb::parallel_for(range, task);
    loop.loopEnded();
}

//! tbb::parallel_for(first, last, body): body(i) for each index.
template <class Index, class Body>
void parallelFor(Index first, Index last, const Body& body) {
    ForkJoin loop;
    const LoopTask<Body> task(loop, body);
    loop.loopStarts();
    tbb::parallel_for(first, last, task);
    loop.loopEnded();
}

//! tbb::parallel_reduce(range, identity, body, reduction).
template <class Range, class Value, class Body, class Reduction>
Value parallelReduce(const Range& range, const Value& identity, const Body& body,
                     const Reduction& reduction) {
    ForkJoin loop;
    const LoopTask<Body> task(loop, body);
    const LoopTask<Reduction, true> merge(loop, reduction);
    loop.loopStarts();
    Value result = tbb::parallel_reduce(range, identity, task, merge);
    loop.loopEnded();
    return result;
}

//! tbb::parallel_deterministic_reduce(range, identity, body, reduction): the same split and the
//! same order of merges on any number of threads.
template <class Range, class Value, class Body, class Reduction>
Value parallelDeterministicReduce(const Range& range, const Value& identity, const Body& body,
                                  const Reduction& reduction) {
    ForkJoin loop;
    const LoopTask<Body> task(loop, body);
    const LoopTask<Reduction, true> merge(loop, reduction);
    loop.loopStarts();
    Value result = tbb::parallel_deterministic_reduce(range, identity, task, merge);
    loop.loopEnded();
    return result;
}

//! tbb::parallel_invoke(first, second): both as tasks, returning when both are done.
template <class First, class Second>
void parallelInvoke(const First& first, const Second& second) {
    ForkJoin loop;
    const LoopTask<First> firstTask(loop, first);
    const LoopTask<Second> secondTask(loop, second);
    loop.loopStarts();
    tbb::parallel_invoke(firstTask, secondTask);
    loop.loopEnded();
}

} // namespace airtrap
