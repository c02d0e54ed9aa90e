#pragma once
// "Did you mean" suggestions for misspelt JSON keys and --set paths.
#include <string>
#include <string_view>
#include <vector>

namespace airtrap {

//! The candidate closest to `word` by edit distance, or an empty string when none is close
//! enough to be a plausible typo (at most a third of the word's length, and at least 2, edits).
std::string closestKey(std::string_view word, const std::vector<std::string>& candidates);

//! "<path>: unknown key; did you mean \"x\"? Valid keys <where>: a, b, c" (the suggestion only
//! when one is close). `where` reads like "of solver" or "at the top level".
std::string unknownKeyMessage(const std::string& path, std::string_view key,
                              const std::vector<std::string>& validKeys, const std::string& where);

//! "a, b, c": for messages that list the valid keys.
std::string joinKeys(const std::vector<std::string>& keys);

} // namespace airtrap
