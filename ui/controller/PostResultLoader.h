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
#include <QThreadPool>
#include <atomic>
#include <memory>
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
    static PostFrameResults load(const std::string& cacheDir, int frame);

    QThreadPool pool_;
    std::atomic<int> latest_{0};
};

} // namespace airtrap

Q_DECLARE_METATYPE(airtrap::PostFrameResults)
