#pragma once
#include <cstddef>

namespace airtrap::bench {

//! Resident-set figures of this process from /proc/self/status, in bytes.
class ProcessMemory {
public:
    //! Starts a new peak: clears the kernel's high-water mark and returns freed heap to the OS
    //! so that the next peak measures only what is allocated from now on.
    static void resetPeak();
    static std::size_t residentBytes();
    static std::size_t peakResidentBytes();
};

} // namespace airtrap::bench
