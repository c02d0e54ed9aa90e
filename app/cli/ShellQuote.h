#pragma once
// Quoting for shell text airtrap-cli writes: the commands it prints for the user to paste (the
// resume hint) and the farm's job scripts, where it is what keeps a value from a scene or a
// wedge (`$(…)`, backquotes, quotes, newlines) from ever being run.
#include <string>

namespace airtrap::cli {

//! `text` as one POSIX shell word: unchanged when it is plainly safe, else in single quotes.
inline std::string shellQuote(const std::string& text) {
    const bool safe =
        !text.empty() && text.find_first_not_of("ABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                                "abcdefghijklmnopqrstuvwxyz"
                                                "0123456789_-.,/:=+@%") == std::string::npos;
    if (safe)
        return text;
    std::string quoted = "'";
    for (const char c : text)
        quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return quoted + "'";
}

} // namespace airtrap::cli
