#include "controller/SimulationController.h"

#include "cache/FrameCache.h"
#include "core/Error.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QDir>
#include <QFile>
#include <QThread>

namespace airtrap {

SimulationController::SimulationController(QObject* parent) : QObject(parent) {
    qRegisterMetaType<BakeProgress>();
    qRegisterMetaType<FrameStats>();
    qRegisterMetaType<State>();
}

SimulationController::~SimulationController() {
    if (!thread_)
        return;
    job_->stop();
    thread_->wait();
}

void SimulationController::bake(const Scene& scene, const QString& cacheDir, bool resume) {
    if (isBusy())
        return;
    cacheDir_ = cacheDir;
    // In the editor a resume after an edit means "go on from here with the new settings".
    const BakeOptions options{.cacheDir = cacheDir.toStdString(),
                              .resume = resume,
                              .overwrite = !resume,
                              .adoptEditedScene = resume};
    job_ = std::make_unique<BakeJob>(scene, options, signallingListener());
    BakeJob* job = job_.get();
    thread_.reset(QThread::create([this, job] { result_ = job->run(); }));
    thread_->setObjectName(QStringLiteral("Airtrap bake"));
    connect(thread_.get(), &QThread::finished, this, &SimulationController::finishBake,
            Qt::QueuedConnection);
    setState(State::Running);
    thread_->start();
}

void SimulationController::pause() {
    if (state_ != State::Running)
        return;
    job_->pause();
    setState(State::Paused);
}

void SimulationController::resume() {
    if (state_ != State::Paused)
        return;
    job_->resume();
    setState(State::Running);
}

void SimulationController::stop() {
    if (state_ != State::Running && state_ != State::Paused)
        return;
    job_->stop();
    setState(State::Stopping);
}

bool SimulationController::waitForIdle(int timeoutMs) {
    if (!thread_)
        return true;
    if (!thread_->wait(QDeadlineTimer(timeoutMs)))
        return false;
    // Deliver what the bake thread posted (its last frames, the finished signal) in order, so
    // callers see the same sequence of signals as they would from the event loop.
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
    finishBake();
    return true;
}

void SimulationController::discardFramesAfter(const QString& cacheDir, int frame) {
    if (isBusy()) {
        Q_EMIT failed(tr("Cannot discard frames of %1 while a bake is running").arg(cacheDir));
        return;
    }
    try {
        FrameCache::open(cacheDir.toStdString()).truncateAfter(frame);
    } catch (const Error& error) {
        Q_EMIT failed(QString::fromStdString(error.what()));
    }
}

bool SimulationController::removeCache(const QString& cacheDir) {
    if (isBusy()) {
        Q_EMIT failed(tr("Cannot delete the cache %1 while a bake is running").arg(cacheDir));
        return false;
    }
    try {
        FrameCache cache = FrameCache::open(cacheDir.toStdString());
        // Frames first (the manifest stops listing them before their files go), then the rest.
        cache.truncateAfter(0);
        QFile::remove(QString::fromStdString(cache.manifestPath()));
    } catch (const Error& error) {
        Q_EMIT failed(QString::fromStdString(error.what()));
        return false;
    }
    QDir(QDir(cacheDir).filePath(QStringLiteral("post"))).removeRecursively();
    return QDir().rmdir(cacheDir);
}

void SimulationController::setState(State state) {
    if (state == state_)
        return;
    state_ = state;
    Q_EMIT stateChanged(state);
}

BakeJob::Listener SimulationController::signallingListener() {
    BakeJob::Listener listener;
    listener.progress = [this](const BakeProgress& report) {
        post([this, report] { Q_EMIT progress(report); });
    };
    listener.frameFinished = [this](int frame, const FrameStats& stats) {
        post([this, frame, stats] { Q_EMIT frameFinished(frame, stats); });
    };
    listener.message = [this](const std::string& text) {
        post([this, text = QString::fromStdString(text)] { Q_EMIT message(text); });
    };
    return listener;
}

void SimulationController::post(std::function<void()> action) {
    // The controller outlives its bake thread (the destructor joins it), and Qt drops calls
    // still queued for a deleted context object, so `this` is safe inside `action`.
    QMetaObject::invokeMethod(this, std::move(action), Qt::QueuedConnection);
}

void SimulationController::finishBake() {
    if (!thread_)
        return;
    thread_->wait();
    thread_.reset();
    job_.reset();
    const BakeResult result = std::exchange(result_, BakeResult{});
    setState(State::Idle);
    const QString text = QString::fromStdString(result.message);
    if (result.outcome == BakeResult::Outcome::Failed)
        Q_EMIT failed(text);
    else
        Q_EMIT finished(result.outcome == BakeResult::Outcome::Completed, text);
}

} // namespace airtrap
