#pragma once
// Ctrl-C (SIGINT) and SIGTERM ask the running bake or export to stop at its next safe point
// instead of killing the process mid-write; a second Ctrl-C quits at once (the cache is still
// consistent then, because every file is replaced atomically).
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

private:
    struct sigaction oldInterrupt_ {};
    struct sigaction oldTerminate_ {};
};

} // namespace airtrap::cli
