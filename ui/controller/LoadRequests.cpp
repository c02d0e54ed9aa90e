#include "controller/LoadRequests.h"

#include <utility>

namespace airtrap {

template <typename Change>
void LoadRequests::update(Change&& change) {
    {
        const std::lock_guard lock(mutex_);
        change(pending_);
    }
    arrived_.notify_one();
}

void LoadRequests::setDirectory(const std::string& directory, int generation) {
    update([&](LoadWork& work) {
        work.directory = directory;
        work.generation = generation;
        // Switching folders re-reads the manifest anyway.
        work.refresh = false;
        work.frame.reset();
    });
}

void LoadRequests::refresh() {
    update([](LoadWork& work) { work.refresh = true; });
}

void LoadRequests::load(int frame) {
    update([frame](LoadWork& work) { work.frame = frame; });
}

void LoadRequests::cancelLoad() {
    const std::lock_guard lock(mutex_);
    pending_.frame.reset();
}

void LoadRequests::quit() {
    update([](LoadWork& work) { work.quit = true; });
}

LoadWork LoadRequests::take() {
    std::unique_lock lock(mutex_);
    arrived_.wait(lock, [this] { return !pending_.empty(); });
    return std::exchange(pending_, LoadWork{});
}

} // namespace airtrap
