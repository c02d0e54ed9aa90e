#pragma once
// Runs the render outputs for the editor — the post stage and exports — on a worker thread of
// their own, so the window stays responsive and a bake can run beside them. Reports arrive as
// queued signals on the thread the controller lives on (the GUI thread).
#include "controller/RenderJob.h"

#include <QObject>
#include <QString>
#include <memory>

class QThread;

namespace airtrap {

class RenderOutputController : public QObject {
    Q_OBJECT

public:
    explicit RenderOutputController(QObject* parent = nullptr);
    //! Stops a running job and waits for its thread (at most one frame).
    ~RenderOutputController() override;

    bool isBusy() const { return thread_ != nullptr; }

    //! Starts `request` on the worker thread; ignored while busy.
    void start(const RenderRequest& request);
    //! Blocks until the job has ended and its signals were delivered, or `timeoutMs` passed.
    //! True when idle on return. For tests and shutdown.
    bool waitForIdle(int timeoutMs);

public Q_SLOTS:
    //! Ends the running job at its next frame; what finished is kept.
    void cancel();

Q_SIGNALS:
    //! A job started; `busy` turns false again just before finished() or failed().
    void busyChanged(bool busy);
    //! `stage` ("post", "export") is `percent` done.
    void progress(const QString& stage, double percent);
    //! The job ended on its own (`completed`) or by cancel(), with a summary.
    void finished(bool completed, const QString& summary);
    //! The job failed with the engine's message.
    void failed(const QString& message);

private:
    void finishJob();

    std::unique_ptr<RenderJob> job_;
    std::unique_ptr<QThread> thread_;
    RenderResult result_; //!< written by the job's thread just before it ends
};

} // namespace airtrap
