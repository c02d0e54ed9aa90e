#include "ProcessMemory.h"

#include <fstream>
#include <malloc.h>
#include <sstream>
#include <string>

namespace airtrap::bench {

namespace {

std::size_t statusField(const std::string& key) {
    std::ifstream status("/proc/self/status");
    std::string line;
    while (std::getline(status, line)) {
        if (line.rfind(key + ":", 0) != 0)
            continue;
        std::istringstream fields(line.substr(key.size() + 1));
        std::size_t kilobytes = 0;
        fields >> kilobytes;
        return kilobytes * 1024;
    }
    return 0;
}

} // namespace

void ProcessMemory::resetPeak() {
    malloc_trim(0);
    // "5" resets VmHWM to the current RSS (Linux ≥ 4.0, proc(5)).
    std::ofstream("/proc/self/clear_refs") << "5";
}

std::size_t ProcessMemory::residentBytes() {
    return statusField("VmRSS");
}

std::size_t ProcessMemory::peakResidentBytes() {
    return statusField("VmHWM");
}

} // namespace airtrap::bench
