#include "timeline/SurfaceLoader.h"

#include "cache/FrameCache.h"
#include "core/Error.h"
#include "post/PostStore.h"

namespace airtrap {

SurfaceLoader::SurfaceLoader(QObject* parent) : QObject(parent) {
    qRegisterMetaType<std::shared_ptr<const TriangleMesh>>();
    pool_.setMaxThreadCount(1);
}

SurfaceLoader::~SurfaceLoader() {
    pool_.clear();
    pool_.waitForDone();
}

std::shared_ptr<const TriangleMesh> SurfaceLoader::load(const std::string& cacheDir, int frame) {
    try {
        const FrameCache cache = FrameCache::open(cacheDir);
        const CacheFrameEntry* source = cache.manifest().findFrame(frame);
        const PostStore store = PostStore::open(cacheDir);
        if (source == nullptr || !store.isCurrent(frame, source->crc32))
            return nullptr;
        return std::make_shared<const TriangleMesh>(store.readFreeSurface(frame));
    } catch (const Error&) {
        return nullptr; // no cache, no post results, or damaged ones: nothing to show
    }
}

void SurfaceLoader::request(const QString& cacheDir, int frame) {
    const int ticket = ++latest_;
    // Older requests still queued are not worth loading: only the newest is shown.
    pool_.clear();
    pool_.start([this, ticket, dir = cacheDir.toStdString(), frame] {
        if (ticket != latest_.load())
            return;
        std::shared_ptr<const TriangleMesh> mesh = load(dir, frame);
        // The destructor waits for this task, so `this` outlives the queued call's creation;
        // Qt drops the call if the object is gone by the time it would run.
        QMetaObject::invokeMethod(
            this,
            [this, ticket, frame, mesh] {
                if (ticket == latest_.load())
                    Q_EMIT surfaceLoaded(frame, mesh);
            },
            Qt::QueuedConnection);
    });
}

} // namespace airtrap
