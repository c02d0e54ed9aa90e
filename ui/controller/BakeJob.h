#pragma once
// One bake as the editor runs it: validation, then the engine's Baker, with pause, resume and
// stop that any thread may call. Knows nothing of Qt; SimulationController runs it on its worker
// thread and turns the listener calls into signals.
#include "bake/Baker.h"
#include "controller/PauseGate.h"
#include "controller/ProgressThrottle.h"
#include "core/Interrupter.h"

#include <chrono>
#include <functional>
#include <optional>
#include <string>

namespace airtrap {

//! How a bake ended.
struct BakeResult {
    enum class Outcome { Completed, Stopped, Failed };

    //! Completed: every frame is baked; Stopped: by stop(); Failed: an engine error.
    Outcome outcome = Outcome::Failed;
    //! "complete", "stopped at frame N", or the engine's message when it failed.
    std::string message;
};

class BakeJob {
public:
    //! Called on the bake thread; each may be empty.
    struct Listener {
        std::function<void(const BakeProgress&)> progress; //!< thinned, see kProgressInterval
        std::function<void(int frame, const FrameStats&)> frameFinished; //!< frame on disk
        std::function<void(const std::string&)> message; //!< warnings and engine notes
    };

    //! Progress reports are thinned to one per this interval (the last one of a frame always
    //! goes through).
    static constexpr std::chrono::milliseconds kProgressInterval{50};

    //! A bake of `scene` with the engine's `options`, reporting to `listener`.
    BakeJob(Scene scene, BakeOptions options, Listener listener);

    //! Validates the scene and bakes; blocks until the bake completes, stops or fails. Never
    //! throws: an engine error becomes a Failed result, every finished frame stays on disk.
    BakeResult run();

    //! Holds the bake after its current step. Thread-safe.
    void pause() { gate_.close(); }
    //! Continues a paused bake. Thread-safe.
    void resume() { gate_.open(); }
    //! Ends the bake after its current step (a paused one at once). Thread-safe.
    void stop();

private:
    BakeResult bake();
    void reportProgress(const BakeProgress& progress);
    void reportFrame(int frame, const FrameStats& stats);
    //! The newest frame in the cache folder (0 when there is none or it cannot be read).
    int lastCachedFrame() const;

    Scene scene_;
    BakeOptions options_;
    Listener listener_;
    Interrupter interrupter_;
    PauseGate gate_;
    ProgressThrottle throttle_{kProgressInterval};
    //! The newest report the throttle held back, delivered before its frame's frameFinished.
    std::optional<BakeProgress> heldBack_;
};

} // namespace airtrap
