#pragma once
// The process exit codes of airtrap-cli; scripts and farms branch on them, so they never change
// meaning (docs/CLI.md).
#include "core/Error.h"

namespace airtrap::cli {

enum class ExitCode : int {
    Success = 0,
    Usage = 1,        //!< the command line could not be parsed
    InvalidInput = 2, //!< invalid scene, bad option value, wrong or existing cache folder
    CacheCorrupt = 3, //!< a damaged frame or manifest
    Io = 4,           //!< cannot read or write: permission denied, disk full
    BlowUp = 5,       //!< the simulation blew up; every good frame is kept
    NotAvailable = 6, //!< a stage or format that comes in a later version
    Scheduler = 7,    //!< farm: no scheduler, or it refused a job or did not answer
    Internal = 70,    //!< an unexpected failure, i.e. a bug (EX_SOFTWARE)
    Requeue = 75,     //!< stopped by SIGUSR1 (a scheduler's warning); run again (EX_TEMPFAIL)
    Stopped = 130,    //!< stopped by Ctrl-C or SIGTERM; the cache is consistent and resumable
};

inline constexpr ExitCode exitCodeFor(ErrorKind kind) {
    switch (kind) {
    case ErrorKind::InvalidScene:
    case ErrorKind::InvalidInput:
        return ExitCode::InvalidInput;
    case ErrorKind::CacheCorrupt:
        return ExitCode::CacheCorrupt;
    case ErrorKind::Io:
        return ExitCode::Io;
    case ErrorKind::SimulationBlowUp:
        return ExitCode::BlowUp;
    case ErrorKind::NotAvailable:
        return ExitCode::NotAvailable;
    }
    return ExitCode::Internal;
}

//! The footer of `airtrap-cli --help`; the same table is in docs/CLI.md.
inline constexpr const char* kExitCodeHelp = R"(Exit codes:
  0    success
  1    usage error (unknown command or option, missing argument)
  2    invalid scene or input (the message names file, JSON path, value and range)
  3    corrupt cache (a damaged frame or manifest, named in the message)
  4    I/O error (permission denied, disk full); the cache stays consistent
  5    simulation blow-up (the message names the frame and the likely cause)
  6    not available yet (a later stage or format)
  7    farm: the scheduler is missing, refused a job or did not answer (nothing stays queued)
  70   internal error (please report it)
  75   stopped by SIGUSR1 (a scheduler's time-limit or preemption warning); the cache is
       consistent: the same command continues (farm jobs requeue themselves)
  130  stopped by Ctrl-C or SIGTERM; continue with `bake --resume`)";

} // namespace airtrap::cli
