#include "controller/RenderOutputController.h"

#include <QCoreApplication>
#include <QDeadlineTimer>
#include <QThread>

namespace airtrap {

RenderOutputController::RenderOutputController(QObject* parent) : QObject(parent) {}

RenderOutputController::~RenderOutputController() {
    if (!thread_)
        return;
    job_->stop();
    thread_->wait();
}

void RenderOutputController::start(const RenderRequest& request) {
    if (isBusy())
        return;
    // The controller outlives the job's thread (the destructor joins it), and Qt drops calls
    // still queued for a deleted context object, so `this` is safe in the posted lambda.
    auto listener = [this](const std::string& stage, double percent) {
        QMetaObject::invokeMethod(
            this,
            [this, stage = QString::fromStdString(stage), percent] {
                Q_EMIT progress(stage, percent);
            },
            Qt::QueuedConnection);
    };
    job_ = std::make_unique<RenderJob>(request, listener);
    RenderJob* job = job_.get();
    thread_.reset(QThread::create([this, job] { result_ = job->run(); }));
    thread_->setObjectName(QStringLiteral("Airtrap render outputs"));
    connect(thread_.get(), &QThread::finished, this, &RenderOutputController::finishJob,
            Qt::QueuedConnection);
    Q_EMIT busyChanged(true);
    thread_->start();
}

void RenderOutputController::cancel() {
    if (job_)
        job_->stop();
}

bool RenderOutputController::waitForIdle(int timeoutMs) {
    if (!thread_)
        return true;
    if (!thread_->wait(QDeadlineTimer(timeoutMs)))
        return false;
    QCoreApplication::sendPostedEvents(this, QEvent::MetaCall);
    finishJob();
    return true;
}

void RenderOutputController::finishJob() {
    if (!thread_)
        return;
    thread_->wait();
    thread_.reset();
    job_.reset();
    const RenderResult result = std::exchange(result_, RenderResult{});
    Q_EMIT busyChanged(false);
    const QString text = QString::fromStdString(result.message);
    if (result.outcome == RenderResult::Outcome::Failed)
        Q_EMIT failed(text);
    else
        Q_EMIT finished(result.outcome == RenderResult::Outcome::Completed, text);
}

} // namespace airtrap
