#include "core/ThreadLimit.h"

#include <tbb/global_control.h>
#include <tbb/info.h>

namespace airtrap {

struct ThreadLimit::Control {
    explicit Control(int threads)
        : control(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads)) {}
    tbb::global_control control;
};

ThreadLimit::ThreadLimit(int threads) {
    const int available = tbb::info::default_concurrency();
    threads_ = threads > 0 ? threads : available;
    // Constructed in place: a copied global_control would release its limit when the temporary
    // dies.
    control_ = std::make_unique<Control>(threads_);
}

ThreadLimit::~ThreadLimit() = default;

} // namespace airtrap
