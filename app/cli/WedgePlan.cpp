#include "WedgePlan.h"

#include "core/AtomicFile.h"
#include "core/Error.h"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <set>

namespace airtrap::cli {

namespace {

//! A value as `--set` writes it: numbers as JSON prints them, strings as they are, vectors as
//! comma-separated numbers.
std::string setSyntax(const nlohmann::ordered_json& value, const std::string& where) {
    if (value.is_string())
        return value.get<std::string>();
    if (value.is_number() || value.is_boolean())
        return value.dump();
    if (value.is_array() && !value.empty() &&
        std::all_of(value.begin(), value.end(), [](const auto& x) { return x.is_number(); })) {
        std::string joined;
        for (const auto& component : value)
            joined += (joined.empty() ? "" : ",") + component.dump();
        return joined;
    }
    throw Error(ErrorKind::InvalidInput, where +
                                             ": expected a number, a string, true/false or an "
                                             "array of numbers, not " +
                                             value.dump());
}

//! `text` reduced to what is safe in a folder name everywhere.
std::string folderSafe(const std::string& text) {
    std::string safe;
    for (const char c : text)
        safe += std::isalnum(static_cast<unsigned char>(c)) || c == '.' || c == '-' ? c : '_';
    return safe.substr(0, 40);
}

std::string wedgeName(const std::vector<std::string>& keys,
                      const std::vector<std::string>& values) {
    if (keys.empty())
        return "base";
    std::string name;
    for (std::size_t i = 0; i < keys.size(); ++i) {
        const std::size_t dot = keys[i].find_last_of(".]");
        const std::string leaf = dot == std::string::npos ? keys[i] : keys[i].substr(dot + 1);
        name += (i == 0 ? "" : "__") + folderSafe(leaf) + "-" + folderSafe(values[i]);
    }
    return name;
}

} // namespace

std::vector<std::string> Wedge::assignments() const {
    std::vector<std::string> result;
    for (std::size_t i = 0; i < keys.size(); ++i)
        result.push_back(keys[i] + "=" + values[i]);
    return result;
}

void WedgePlan::add(const std::string& key, const std::string& value) {
    const auto at = std::find(keys_.begin(), keys_.end(), key);
    if (at == keys_.end()) {
        keys_.push_back(key);
        values_.push_back({value});
        return;
    }
    std::vector<std::string>& values = values_[std::size_t(at - keys_.begin())];
    if (std::find(values.begin(), values.end(), value) == values.end())
        values.push_back(value);
}

void WedgePlan::addAssignments(const std::vector<std::string>& assignments) {
    for (const std::string& assignment : assignments) {
        const std::size_t equals = assignment.find('=');
        if (equals == std::string::npos || equals == 0)
            throw Error(ErrorKind::InvalidInput, "--wedge " + assignment +
                                                     ": expected key=VALUE, e.g. "
                                                     "solver.viscosity_alpha=0.05");
        add(assignment.substr(0, equals), assignment.substr(equals + 1));
    }
}

void WedgePlan::addFile(const std::string& path) {
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    const auto json = nlohmann::ordered_json::parse(bytes.begin(), bytes.end(), nullptr, false);
    if (json.is_discarded() || !json.is_object())
        throw Error(ErrorKind::InvalidInput,
                    path + ": expected a JSON object of keys and their values, e.g. "
                           "{\"solver.viscosity_alpha\": [0.05, 0.2]}");
    for (const auto& [key, value] : json.items()) {
        const std::string where = path + ": \"" + key + "\"";
        if (!value.is_array() || value.empty())
            throw Error(ErrorKind::InvalidInput,
                        where + ": expected an array of the key's values, e.g. [0.05, 0.2] (a "
                                "vector value is an array inside it: [[0, 1, 0], [0, 2, 0]])");
        for (const auto& one : value)
            add(key, setSyntax(one, where));
    }
}

std::vector<Wedge> WedgePlan::wedges() const {
    std::vector<Wedge> result;
    std::size_t count = 1;
    for (const auto& values : values_)
        count *= values.size();
    std::set<std::string> names;
    for (std::size_t index = 0; index < count; ++index) {
        Wedge wedge;
        wedge.keys = keys_;
        std::size_t rest = index;
        for (std::size_t k = keys_.size(); k-- > 0;) {
            wedge.values.insert(wedge.values.begin(), values_[k][rest % values_[k].size()]);
            rest /= values_[k].size();
        }
        wedge.name = wedgeName(wedge.keys, wedge.values);
        for (int copy = 2; !names.insert(wedge.name).second; ++copy)
            wedge.name = wedgeName(wedge.keys, wedge.values) + "-" + std::to_string(copy);
        result.push_back(std::move(wedge));
    }
    return result;
}

} // namespace airtrap::cli
