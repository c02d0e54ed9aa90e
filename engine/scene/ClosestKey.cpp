#include "scene/ClosestKey.h"

#include <algorithm>
#include <cstddef>

namespace airtrap {
namespace {

//! Levenshtein distance with one rolling row; keys are short, so this is cheap.
std::size_t editDistance(std::string_view a, std::string_view b) {
    std::vector<std::size_t> row(b.size() + 1);
    for (std::size_t j = 0; j <= b.size(); ++j)
        row[j] = j;
    for (std::size_t i = 1; i <= a.size(); ++i) {
        std::size_t diagonal = row[0];
        row[0] = i;
        for (std::size_t j = 1; j <= b.size(); ++j) {
            const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
            diagonal = row[j];
            row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
        }
    }
    return row[b.size()];
}

} // namespace

std::string closestKey(std::string_view word, const std::vector<std::string>& candidates) {
    const std::size_t limit = std::max<std::size_t>(2, word.size() / 3);
    std::string best;
    std::size_t bestDistance = limit + 1;
    for (const std::string& candidate : candidates) {
        const std::size_t distance = editDistance(word, candidate);
        if (distance < bestDistance) {
            best = candidate;
            bestDistance = distance;
        }
    }
    return best;
}

std::string unknownKeyMessage(const std::string& path, std::string_view key,
                              const std::vector<std::string>& validKeys, const std::string& where) {
    std::string message = path + ": unknown key";
    const std::string suggestion = closestKey(key, validKeys);
    if (!suggestion.empty())
        message += "; did you mean \"" + suggestion + "\"?";
    return message + (suggestion.empty() ? "; valid" : " Valid") + " keys " + where + ": " +
           joinKeys(validKeys);
}

std::string joinKeys(const std::vector<std::string>& keys) {
    std::string text;
    for (const std::string& key : keys)
        text += (text.empty() ? "" : ", ") + key;
    return text;
}

} // namespace airtrap
