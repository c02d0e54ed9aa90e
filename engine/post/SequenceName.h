#pragma once
#include <cstdio>
#include <string>

namespace airtrap {

//! The file of `frame` in an exported sequence: "water_0001.obj" for ("water", 1, "obj"). Four
//! digits from frame 1, more from frame 10000 on (docs/CLI.md "export"), so every renderer's
//! frame-number pattern (####, $F4, %04d) finds the files without renaming.
inline std::string sequenceFileName(const std::string& stem, int frame, const std::string& ext) {
    char digits[16];
    std::snprintf(digits, sizeof digits, "%04d", frame);
    return stem + "_" + digits + "." + ext;
}

} // namespace airtrap
