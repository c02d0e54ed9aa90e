#include "controller/PostResultLoader.h"

#include "cache/FrameCache.h"
#include "core/Error.h"
#include "post/PostStore.h"
#include "post/SubgridStore.h"

namespace airtrap {

namespace {

std::shared_ptr<const TriangleMesh> loadSurface(const std::string& cacheDir,
                                                const CacheFrameEntry& source) {
    try {
        const PostStore store = PostStore::open(cacheDir);
        if (!store.isCurrent(source.frame, source.crc32))
            return nullptr;
        return std::make_shared<const TriangleMesh>(store.readFreeSurface(source.frame));
    } catch (const Error&) {
        return nullptr; // damaged: nothing to show
    }
}

std::vector<SubgridBubble> loadSubgridBubbles(const std::string& cacheDir,
                                              const CacheManifest& manifest, int frame) {
    try {
        const SubgridStore store = SubgridStore::open(cacheDir);
        if (!store.isCurrentIn(manifest, frame))
            return {};
        return store.readFrame(frame).bubbles;
    } catch (const Error&) {
        return {}; // damaged: nothing to show
    }
}

} // namespace

PostResultLoader::PostResultLoader(QObject* parent) : QObject(parent) {
    qRegisterMetaType<PostFrameResults>();
    thread_ = std::thread([this] { serve(); });
}

PostResultLoader::~PostResultLoader() {
    {
        const std::lock_guard lock(mutex_);
        quit_ = true;
    }
    arrived_.notify_one();
    thread_.join();
}

void PostResultLoader::serve() {
    for (;;) {
        Request request;
        {
            std::unique_lock lock(mutex_);
            arrived_.wait(lock, [this] { return quit_ || waiting_.has_value(); });
            if (quit_)
                return;
            request = std::move(*waiting_);
            waiting_.reset();
        }
        if (request.ticket != latest_.load())
            continue;
        PostFrameResults results = load(request.cacheDir, request.frame);
        // The destructor joins this thread, so `this` outlives the queued call's creation; Qt
        // drops the call if the object is gone by the time it would run.
        QMetaObject::invokeMethod(
            this,
            [this, ticket = request.ticket, frame = request.frame, results = std::move(results)] {
                if (ticket == latest_.load())
                    Q_EMIT resultsLoaded(frame, results);
            },
            Qt::QueuedConnection);
    }
}

PostFrameResults PostResultLoader::load(const std::string& cacheDir, int frame) {
    CacheManifest manifest;
    try {
        manifest = FrameCache::open(cacheDir).manifest();
    } catch (const Error&) {
        return {}; // no cache: nothing to show
    }
    const CacheFrameEntry* source = manifest.findFrame(frame);
    if (source == nullptr)
        return {};
    return {loadSurface(cacheDir, *source), loadSubgridBubbles(cacheDir, manifest, frame)};
}

void PostResultLoader::request(const QString& cacheDir, int frame) {
    const int ticket = ++latest_;
    {
        // An older request still waiting is not worth loading: only the newest is shown.
        const std::lock_guard lock(mutex_);
        waiting_ = Request{cacheDir.toStdString(), frame, ticket};
    }
    arrived_.notify_one();
}

} // namespace airtrap
