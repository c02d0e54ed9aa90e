#include "core/ThreadLimit.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

namespace airtrap {

struct ThreadLimit::Control {
    tbb::global_control control;
};

ThreadLimit::ThreadLimit(int threads) {
    const int available = tbb::info::default_concurrency();
    threads_ = threads > 0 ? threads : available;
    control_ = std::make_unique<Control>(
        Control{tbb::global_control(tbb::global_control::max_allowed_parallelism, threads_)});
}

ThreadLimit::~ThreadLimit() = default;

} // namespace airtrap
