#include "SignalStopper.h"

#include <atomic>
#include <unistd.h>

namespace airtrap::cli {

namespace {

// Only lock-free atomics may be touched from a signal handler; requestStop() is one relaxed
// store to such an atomic, so the handler may call it directly.
static_assert(std::atomic<Interrupter*>::is_always_lock_free);
static_assert(std::atomic<bool>::is_always_lock_free);

std::atomic<Interrupter*> target{nullptr};
volatile std::sig_atomic_t receivedSignal = 0;

extern "C" void onStopSignal(int signal) {
    receivedSignal = signal;
    if (Interrupter* interrupter = target.load())
        interrupter->requestStop();
    // write() is async-signal-safe; iostreams are not.
    static const char byUser[] = "\nnote: stopping after the current step (Ctrl-C again to quit "
                                 "at once)\n";
    static const char byScheduler[] = "\nnote: SIGUSR1 (time limit or preemption ahead): "
                                      "stopping after the current step\n";
    const bool scheduled = signal == SIGUSR1;
    [[maybe_unused]] const ssize_t ignored =
        ::write(STDERR_FILENO, scheduled ? byScheduler : byUser,
                (scheduled ? sizeof byScheduler : sizeof byUser) - 1);
}

void install(int signal, struct sigaction& old) {
    struct sigaction action {};
    action.sa_handler = onStopSignal;
    sigemptyset(&action.sa_mask);
    // SA_RESETHAND: the second signal gets the default action, i.e. quits at once.
    action.sa_flags = SA_RESETHAND | SA_RESTART;
    ::sigaction(signal, &action, &old);
}

} // namespace

SignalStopper::SignalStopper(Interrupter& interrupter) {
    receivedSignal = 0;
    target.store(&interrupter);
    install(SIGINT, oldInterrupt_);
    install(SIGTERM, oldTerminate_);
    install(SIGUSR1, oldUser1_);
}

SignalStopper::~SignalStopper() {
    ::sigaction(SIGINT, &oldInterrupt_, nullptr);
    ::sigaction(SIGTERM, &oldTerminate_, nullptr);
    ::sigaction(SIGUSR1, &oldUser1_, nullptr);
    target.store(nullptr);
}

int SignalStopper::received() {
    return receivedSignal;
}

ExitCode SignalStopper::stoppedExitCode() {
    return receivedSignal == SIGUSR1 ? ExitCode::Requeue : ExitCode::Stopped;
}

} // namespace airtrap::cli
