#include "controller/FrameLoader.h"

#include <QThread>

namespace airtrap {

FrameLoader::FrameLoader(QObject* parent) : FrameLoader(FrameLru::Limits{}, parent) {}

FrameLoader::FrameLoader(FrameLru::Limits limits, QObject* parent) : QObject(parent), lru_(limits) {
    qRegisterMetaType<std::shared_ptr<const FrameData>>();
    thread_.reset(QThread::create([this] { serve(); }));
    thread_->setObjectName(QStringLiteral("Airtrap frame loader"));
    thread_->start();
}

FrameLoader::~FrameLoader() {
    requests_.quit();
    thread_->wait();
}

std::vector<int> FrameLoader::cachedFrames() const {
    const std::lock_guard lock(mutex_);
    return frames_;
}

void FrameLoader::setCacheDirectory(const QString& directory) {
    directory_ = directory;
    ++generation_;
    latestRequest_.reset();
    {
        const std::lock_guard lock(mutex_);
        lru_.clear();
        lruGeneration_ = generation_;
        frames_.clear();
    }
    requests_.setDirectory(directory.toStdString(), generation_);
}

void FrameLoader::request(int frame) {
    latestRequest_ = frame;
    std::shared_ptr<const FrameData> kept;
    {
        const std::lock_guard lock(mutex_);
        kept = lru_.find(frame);
    }
    if (!kept) {
        requests_.load(frame);
        return;
    }
    // Answered from memory; an older frame still waiting for the loader is not wanted anymore.
    // The answer is queued like a load's, so callers see one behaviour.
    requests_.cancelLoad();
    post([this, frame, generation = generation_, kept] { deliverFrame(frame, generation, kept); });
}

void FrameLoader::refresh() {
    requests_.refresh();
}

void FrameLoader::deliverFrame(int frame, int generation,
                               const std::shared_ptr<const FrameData>& data) {
    if (answersLatestRequest(frame, generation))
        Q_EMIT frameLoaded(frame, data);
}

void FrameLoader::deliverFailure(int frame, int generation, const QString& message) {
    if (answersLatestRequest(frame, generation))
        Q_EMIT loadFailed(frame, message);
}

void FrameLoader::deliverListing(int generation, const QList<int>& frames) {
    if (generation == generation_)
        Q_EMIT framesListed(frames);
}

void FrameLoader::deliverOutputListing(int generation, const QList<int>& frames) {
    if (generation == generation_)
        Q_EMIT renderOutputsListed(frames);
}

bool FrameLoader::answersLatestRequest(int frame, int generation) {
    if (generation != generation_ || latestRequest_ != frame)
        return false;
    // One answer per request: a second result for the same frame (from memory and from disk)
    // would only make the viewport redraw.
    latestRequest_.reset();
    return true;
}

void FrameLoader::post(std::function<void()> action) {
    // The destructor joins the loader thread, and Qt drops calls queued for a deleted object.
    QMetaObject::invokeMethod(this, std::move(action), Qt::QueuedConnection);
}

void FrameLoader::serve() {
    for (;;) {
        const LoadWork work = requests_.take();
        if (work.quit)
            return;
        perform(work);
    }
}

void FrameLoader::perform(const LoadWork& work) {
    if (work.directory) {
        loaderGeneration_ = work.generation;
        reader_.open(*work.directory);
        publishListing(true);
        publishOutputListing();
    }
    if (work.refresh) {
        reader_.reload();
        publishListing(true);
        publishOutputListing();
    }
    if (work.frame)
        load(*work.frame);
}

void FrameLoader::load(int frame) {
    loads_.fetch_add(1);
    std::shared_ptr<const FrameData> data;
    QString failure;
    try {
        data = std::make_shared<const FrameData>(reader_.read(frame));
    } catch (const std::exception& error) {
        // airtrap::Error with the user's message, or out of memory for a huge frame.
        failure = QString::fromStdString(error.what());
    }
    // Reading may have re-read the manifest: drop what changed before keeping the new data.
    publishListing(false);
    const int generation = loaderGeneration_;
    if (!data) {
        post([this, frame, generation, failure] { deliverFailure(frame, generation, failure); });
        return;
    }
    keep(frame, data);
    post([this, frame, generation, data] { deliverFrame(frame, generation, data); });
}

void FrameLoader::publishListing(bool always) {
    const std::vector<int> frames = reader_.frames();
    const std::vector<int> changed = reader_.takeChangedFrames();
    {
        const std::lock_guard lock(mutex_);
        if (lruGeneration_ == loaderGeneration_) {
            for (int frame : changed)
                lru_.erase(frame);
            frames_ = frames;
        }
    }
    if (!always && frames == listed_)
        return;
    listed_ = frames;
    const QList<int> list(frames.begin(), frames.end());
    post([this, generation = loaderGeneration_, list] { deliverListing(generation, list); });
}

void FrameLoader::publishOutputListing() {
    std::vector<int> frames;
    try {
        frames = reader_.renderOutputFrames();
    } catch (const std::exception&) {
        // An unreadable render output list marks nothing; the outputs' own loader says why.
    }
    const QList<int> list(frames.begin(), frames.end());
    post([this, generation = loaderGeneration_, list] { deliverOutputListing(generation, list); });
}

void FrameLoader::keep(int frame, const std::shared_ptr<const FrameData>& data) {
    const std::lock_guard lock(mutex_);
    // A result from a folder the GUI has already left must not mix into the new one's frames.
    if (lruGeneration_ == loaderGeneration_)
        lru_.insert(frame, data);
}

} // namespace airtrap
