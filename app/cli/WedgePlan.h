#pragma once
// The wedges of `farm submit` (docs/FARM.md "farm submit"): one bake per combination of parameter
// values, the way an artist explores a look. `--wedge key=VALUE` repeated for one key adds a
// value; different keys make the cross product. Values keep `--set`'s syntax (a vector stays
// `1,2,0.5`), so a wedge is the scene with a list of `--set` assignments.
#include "Wedge.h"

#include <string>
#include <vector>

namespace airtrap::cli {

class WedgePlan {
public:
    //! Adds `--wedge` assignments ("key=value"); Error(InvalidInput) naming one without '='.
    void addAssignments(const std::vector<std::string>& assignments);
    //! Adds the values of a wedge file: a JSON object whose members are keys, each with the
    //! array of its values (numbers, strings, booleans; a vector is an array of numbers inside
    //! it). Error(InvalidInput) naming the file and the member when it is not so.
    void addFile(const std::string& path);

    //! Every combination, the first key varying slowest. One wedge without values when nothing
    //! was added. Names are made unique.
    std::vector<Wedge> wedges() const;

private:
    void add(const std::string& key, const std::string& value);

    std::vector<std::string> keys_;
    std::vector<std::vector<std::string>> values_; //!< per key, in the order given
};

} // namespace airtrap::cli
