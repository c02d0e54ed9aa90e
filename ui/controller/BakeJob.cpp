#include "controller/BakeJob.h"

#include "cache/FrameCache.h"
#include "core/Error.h"
#include "sim/SceneCheck.h"

#include <exception>

namespace airtrap {

BakeJob::BakeJob(Scene scene, BakeOptions options, Listener listener)
    : scene_(std::move(scene)), options_(std::move(options)), listener_(std::move(listener)) {}

void BakeJob::stop() {
    interrupter_.requestStop();
    gate_.release();
}

BakeResult BakeJob::run() {
    try {
        return bake();
    } catch (const Error& error) {
        return {BakeResult::Outcome::Failed, error.what()};
    } catch (const std::exception& error) {
        // Out of memory or a library's own exception: still the end of this bake, not of the
        // editor.
        return {BakeResult::Outcome::Failed, std::string("bake failed: ") + error.what()};
    }
}

BakeResult BakeJob::bake() {
    std::vector<std::string> notes;
    for (const std::string& warning : validateScene(scene_, &notes))
        if (listener_.message)
            listener_.message("warning: " + warning);
    for (const std::string& note : notes)
        if (listener_.message)
            listener_.message("note: " + note);
    Baker baker(scene_, options_);
    baker.onProgress([this](const BakeProgress& progress) { reportProgress(progress); });
    baker.onFrame([this](int frame, const FrameStats& stats) { reportFrame(frame, stats); });
    baker.onMessage([this](const std::string& text) {
        if (listener_.message)
            listener_.message(text);
    });
    if (baker.run(interrupter_) == Baker::Outcome::Completed)
        return {BakeResult::Outcome::Completed, "complete"};
    return {BakeResult::Outcome::Stopped, "stopped at frame " + std::to_string(lastCachedFrame())};
}

void BakeJob::reportProgress(const BakeProgress& progress) {
    if (throttle_.admit(ProgressThrottle::Clock::now())) {
        heldBack_.reset();
        if (listener_.progress)
            listener_.progress(progress);
    } else {
        heldBack_ = progress;
    }
    // The pause waits here, between two steps, with the simulation's state intact.
    gate_.pass();
}

void BakeJob::reportFrame(int frame, const FrameStats& stats) {
    if (heldBack_ && listener_.progress)
        listener_.progress(*heldBack_);
    heldBack_.reset();
    if (listener_.frameFinished)
        listener_.frameFinished(frame, stats);
}

int BakeJob::lastCachedFrame() const {
    try {
        const std::vector<int> frames = FrameCache::open(options_.cacheDir).frames();
        return frames.empty() ? 0 : frames.back();
    } catch (const Error&) {
        return 0;
    }
}

} // namespace airtrap
