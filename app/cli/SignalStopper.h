#pragma once
// Ctrl-C (SIGINT) and SIGTERM ask the running bake or export to stop at its next safe point
// instead of killing the process mid-write; a second Ctrl-C quits at once (the cache is still
// consistent then, because every file is replaced atomically). SIGUSR1 asks the same, for a
// scheduler that warns a job before its time limit or a preemption (docs/FARM.md); it ends with
// its own exit code, so the job script tells it from a cancel and requeues.
#include "ExitCode.h"
#include "core/Interrupter.h"

#include <csignal>

namespace airtrap::cli {

class SignalStopper {
public:
    //! Installs the handlers; they call `interrupter.requestStop()`. One instance at a time.
    explicit SignalStopper(Interrupter& interrupter);
    //! Restores the handlers that were there before.
    ~SignalStopper();
    SignalStopper(const SignalStopper&) = delete;
    SignalStopper& operator=(const SignalStopper&) = delete;

    //! The signal that asked to stop, or 0.
    static int received();
    //! The exit code of a run that stopped when asked: Requeue for SIGUSR1, else Stopped.
    static ExitCode stoppedExitCode();

private:
    struct sigaction oldInterrupt_ {};
    struct sigaction oldTerminate_ {};
    struct sigaction oldUser1_ {};
};

} // namespace airtrap::cli
