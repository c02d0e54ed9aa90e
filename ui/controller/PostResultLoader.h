#pragma once
// Loads the post results of the frame the timeline shows from beside the cache: its free-surface
// mesh (PostStore) and its sub-grid bubbles (SubgridStore), on a thread of its own, so a mesh of a
// million triangles never stalls the GUI. Only the newest request is answered. A result that is
// not current (no post run yet, or the frame was re-baked since) is answered as absent, as is a
// damaged one: the viewport then shows the particles and trapped bubbles alone.
#include "post/SubgridBubble.h"
#include "rigid/TriangleMesh.h"

#include <QObject>
#include <QString>
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

namespace airtrap {

struct PostFrameResults {
    std::shared_ptr<const TriangleMesh> surface; //!< null when the frame has none
    std::vector<SubgridBubble> subgridBubbles;   //!< empty when the frame has none
};

class PostResultLoader : public QObject {
    Q_OBJECT

public:
    explicit PostResultLoader(QObject* parent = nullptr);
    //! Waits for a load in progress.
    ~PostResultLoader() override;

public Q_SLOTS:
    void request(const QString& cacheDir, int frame);

Q_SIGNALS:
    void resultsLoaded(int frame, const airtrap::PostFrameResults& results);

private:
    struct Request {
        std::string cacheDir;
        int frame = 0;
        int ticket = 0; //!< the value of latest_ when it was asked for
    };

    //! The loader thread: takes the waiting request, loads it, posts the results.
    void serve();
    static PostFrameResults load(const std::string& cacheDir, int frame);

    // A std::thread and a std::mutex rather than a QThreadPool: the thread sanitizer build sees
    // their order, not that of Qt's pool (docs/TESTING.md "Sanitizers").
    std::mutex mutex_;
    std::condition_variable arrived_;
    std::optional<Request> waiting_; //!< only the newest: a newer request replaces it
    bool quit_ = false;
    std::atomic<int> latest_{0};
    std::thread thread_;
};

} // namespace airtrap

Q_DECLARE_METATYPE(airtrap::PostFrameResults)
