#pragma once
// One wedge of a farm submission (WedgePlan): the scene with a value for each wedged key.
#include <string>
#include <vector>

namespace airtrap::cli {

struct Wedge {
    //! Folder name: each key's last part and its value, e.g. "viscosity_alpha-0.05"; "base"
    //! when nothing is wedged.
    std::string name;
    std::vector<std::string> keys;   //!< in the order given
    std::vector<std::string> values; //!< one per key, `--set` syntax
    //! "key=value" for each key, as `--set` takes them.
    std::vector<std::string> assignments() const;
};

} // namespace airtrap::cli
