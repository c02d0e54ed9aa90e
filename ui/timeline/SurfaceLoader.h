#pragma once
// Loads the free-surface mesh of the frame the timeline shows from the post results beside the
// cache (PostStore), on a thread of its own, so a mesh of a million triangles never stalls the
// GUI. Only the newest request is answered. A frame without a current result (no post run yet,
// or the frame was re-baked since) is answered with no mesh, as is a damaged one: the viewport
// then shows the particles alone.
#include "rigid/TriangleMesh.h"

#include <QObject>
#include <QString>
#include <QThreadPool>
#include <atomic>
#include <memory>

namespace airtrap {

class SurfaceLoader : public QObject {
    Q_OBJECT

public:
    explicit SurfaceLoader(QObject* parent = nullptr);
    //! Waits for a load in progress.
    ~SurfaceLoader() override;

public Q_SLOTS:
    void request(const QString& cacheDir, int frame);

Q_SIGNALS:
    //! The mesh of `frame`, or null when it has none.
    void surfaceLoaded(int frame, std::shared_ptr<const airtrap::TriangleMesh> mesh);

private:
    static std::shared_ptr<const TriangleMesh> load(const std::string& cacheDir, int frame);

    QThreadPool pool_;
    std::atomic<int> latest_{0};
};

} // namespace airtrap

Q_DECLARE_METATYPE(std::shared_ptr<const airtrap::TriangleMesh>)
