#pragma once
// Runs bakes for the editor on a worker thread, so the window stays responsive while the engine
// computes. The controller bakes a copy of the scene: editing the document during a bake changes
// nothing in it. Everything it reports arrives as queued signals on the thread it lives on (the
// GUI thread).
#include "bake/Baker.h"
#include "controller/BakeJob.h"
#include "scene/Scene.h"
#include "sim/FrameStats.h"

#include <QObject>
#include <QString>
#include <memory>

class QThread;

namespace airtrap {

class SimulationController : public QObject {
    Q_OBJECT

public:
    enum class State {
        Idle,     //!< no bake
        Running,  //!< baking
        Paused,   //!< a bake holds after its current step until resume() or stop()
        Stopping, //!< stop() was asked; the bake ends after its current step
    };
    Q_ENUM(State)

    explicit SimulationController(QObject* parent = nullptr);
    //! Stops a running bake and waits for its thread (at most one step).
    ~SimulationController() override;

    //! What the controller is doing now.
    State state() const { return state_; }
    //! True unless Idle: a bake is running, paused or stopping.
    bool isBusy() const { return state_ != State::Idle; }
    //! The folder of the current or last bake (empty before the first).
    QString cacheDir() const { return cacheDir_; }

    //! Bakes `scene` into `cacheDir` on the worker thread. `resume` continues the folder's cache
    //! from its last good frame (a folder without a cache starts fresh), with the scene's edited
    //! settings if it was edited since (BakeOptions::adoptEditedScene); otherwise an existing
    //! cache there is replaced. Validation errors and engine errors arrive as failed(). Ignored
    //! while busy.
    void bake(const Scene& scene, const QString& cacheDir, bool resume);
    //! Deletes every frame after `frame` from the cache in `cacheDir` (e.g. before re-baking the
    //! rest with changed parameters). Only while Idle; errors arrive as failed().
    void discardFramesAfter(const QString& cacheDir, int frame);
    //! Deletes the cache in `cacheDir` (not while a bake runs): its frames, its manifest and the
    //! render outputs made from them (post/), then the folder itself when nothing else is left in
    //! it. Other files (an export/ folder) stay. True when the folder is gone; failures are
    //! emitted as failed().
    bool removeCache(const QString& cacheDir);

    //! Blocks the calling (GUI) thread until the bake has ended and its final signals have been
    //! delivered, or until `timeoutMs` passed. True when Idle on return. For tests and shutdown.
    bool waitForIdle(int timeoutMs);

public Q_SLOTS:
    //! Holds a running bake after its current step; nothing is lost, resume() continues it.
    void pause();
    //! Continues a paused bake.
    void resume();
    //! Ends a running or paused bake after its current step; every finished frame stays cached.
    void stop();

Q_SIGNALS:
    //! The state changed to `state`.
    void stateChanged(airtrap::SimulationController::State state);
    //! Progress of the frame being computed, at most ~20 per second plus the last of each frame.
    void progress(const airtrap::BakeProgress& progress);
    //! Frame `frame` is on disk and may be loaded.
    void frameFinished(int frame, const airtrap::FrameStats& stats);
    //! A note for the user: validation warnings, skipped damaged frames, where a resume starts.
    void message(const QString& text);
    //! The bake ended on its own (`completed`) or by stop(); `status` is "complete" or "stopped
    //! at frame N". The state is already Idle.
    void finished(bool completed, const QString& status);
    //! The bake or a discard failed with the engine's message; the frames finished before it are
    //! still on disk. After a failed bake the state is already Idle.
    void failed(const QString& engineMessage);

private:
    void setState(State state);
    //! Listener callbacks for the bake thread that re-emit on this object's thread.
    BakeJob::Listener signallingListener();
    //! Calls `action` on this object's thread, after everything posted before it.
    void post(std::function<void()> action);
    //! Joins the finished bake thread and reports how the bake ended. Does nothing when no bake
    //! thread exists, so the thread's finished signal and waitForIdle() may both call it.
    void finishBake();

    State state_ = State::Idle;
    QString cacheDir_;
    std::unique_ptr<BakeJob> job_;
    std::unique_ptr<QThread> thread_;
    //! Written by the bake thread just before it ends; read after joining it.
    BakeResult result_;
};

} // namespace airtrap

Q_DECLARE_METATYPE(airtrap::BakeProgress)
Q_DECLARE_METATYPE(airtrap::FrameStats)
