#pragma once
// Loads cached frames for the viewport on a thread of its own, so that reading and checking a
// large frame never stalls the GUI. Recent frames stay in memory (FrameLru); requests merge, and
// only the answer to the newest request is delivered, so scrubbing shows where the user is now,
// not where they were.
#include "cache/FrameFile.h"
#include "controller/CacheReader.h"
#include "controller/FrameLru.h"
#include "controller/LoadRequests.h"

#include <QList>
#include <QObject>
#include <QString>
#include <atomic>
#include <functional>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

class QThread;

namespace airtrap {

class FrameLoader : public QObject {
    Q_OBJECT

public:
    //! Keeps the FrameLru's default of 8 frames and 512 MiB.
    explicit FrameLoader(QObject* parent = nullptr);
    explicit FrameLoader(FrameLru::Limits limits, QObject* parent = nullptr);
    //! Ends the loader thread (after the load in progress, if any).
    ~FrameLoader() override;

    //! The folder frames are loaded from (empty = none).
    QString cacheDirectory() const { return directory_; }
    //! The frames the cache listed when the loader thread last read its manifest.
    std::vector<int> cachedFrames() const;
    //! Frames read from disk so far (answers from memory not counted); for tests and diagnostics.
    int loadsPerformed() const { return loads_.load(); }

public Q_SLOTS:
    //! Loads from the cache in `directory` from now on (empty = none); forgets the frames kept
    //! from the previous one. Set it again when a fresh bake starts over the same folder.
    void setCacheDirectory(const QString& directory);
    //! Asks for `frame`; answered by frameLoaded() or loadFailed(), unless a newer request
    //! comes first (then only the newest is answered).
    void request(int frame);
    //! Re-reads the manifest, e.g. after frames were discarded; answered by framesListed().
    void refresh();

Q_SIGNALS:
    //! The newest requested frame, read and verified.
    void frameLoaded(int frame, std::shared_ptr<const airtrap::FrameData> data);
    //! The newest requested frame cannot be shown: not cached, or damaged (the message names
    //! the file).
    void loadFailed(int frame, const QString& message);
    //! The frames the cache lists, ascending; sent after opening a folder, after refresh(), and
    //! whenever a load found the list changed.
    void framesListed(const QList<int>& frames);
    //! The cached frames with render outputs made from them as they are now, ascending; sent
    //! after opening a folder and after refresh() (call it when a post run made outputs).
    void renderOutputsListed(const QList<int>& frames);

private:
    // GUI thread.
    void deliverFrame(int frame, int generation, const std::shared_ptr<const FrameData>& data);
    void deliverFailure(int frame, int generation, const QString& message);
    void deliverListing(int generation, const QList<int>& frames);
    void deliverOutputListing(int generation, const QList<int>& frames);
    //! True (once) when a result for `frame` answers the newest request of the current folder.
    bool answersLatestRequest(int frame, int generation);
    //! Calls `action` on the GUI thread.
    void post(std::function<void()> action);

    // Loader thread.
    void serve();
    void perform(const LoadWork& work);
    void load(int frame);
    //! Drops stale frames from memory and tells the GUI when the list changed (or `always`).
    void publishListing(bool always);
    //! Tells the GUI which cached frames have render outputs.
    void publishOutputListing();
    void keep(int frame, const std::shared_ptr<const FrameData>& data);

    // GUI thread only.
    QString directory_;
    //! Counts folder switches; results tagged with an older one are dropped.
    int generation_ = 0;
    std::optional<int> latestRequest_;

    // Loader thread only.
    CacheReader reader_;
    int loaderGeneration_ = 0;
    std::vector<int> listed_;

    // Shared, guarded by mutex_.
    mutable std::mutex mutex_;
    FrameLru lru_;
    //! The folder generation the LRU's frames belong to.
    int lruGeneration_ = 0;
    std::vector<int> frames_;

    LoadRequests requests_;
    std::atomic<int> loads_{0};
    std::unique_ptr<QThread> thread_;
};

} // namespace airtrap

Q_DECLARE_METATYPE(std::shared_ptr<const airtrap::FrameData>)
