#pragma once
// `words` with `separator` between them: job ids for sbatch and scancel, keys for messages.
#include <string>
#include <vector>

namespace airtrap::cli {

inline std::string joined(const std::vector<std::string>& words, const std::string& separator) {
    std::string text;
    for (const std::string& word : words) {
        if (!text.empty())
            text += separator;
        text += word;
    }
    return text;
}

} // namespace airtrap::cli
