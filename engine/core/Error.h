#pragma once
#include <stdexcept>
#include <string>

namespace airtrap {

//! What went wrong, so the CLI can choose an exit code and the editor a dialog title.
enum class ErrorKind {
    InvalidScene,     //!< malformed or out-of-range scene (file, JSON path, value, allowed range)
    InvalidInput,     //!< other bad input: a mesh, a command-line value
    CacheCorrupt,     //!< a frame or manifest that fails its checks
    Io,               //!< cannot read or write: permission denied, disk full
    SimulationBlowUp, //!< NaN, particles leaving the domain, density error beyond its bound
    NotAvailable,     //!< a stage or format that does not exist yet
};

//! The one exception type of the engine; its message is meant for the user as it is.
class Error : public std::runtime_error {
public:
    Error(ErrorKind kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
    ErrorKind kind() const { return kind_; }

private:
    ErrorKind kind_;
};

} // namespace airtrap
