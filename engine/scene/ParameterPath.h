#pragma once
// Where a dotted path such as "fluid_blocks[1].max" points in the scene schema.
#include "scene/SchemaSection.h"

#include <cstddef>
#include <string>

namespace airtrap {

struct ParameterPath {
    const SchemaSection* section = nullptr;
    const BoundParameter* parameter = nullptr;
    std::size_t element = 0; //!< index into an array section; 0 elsewhere
    std::string text;        //!< canonical form, as printed in messages: "fluid_blocks[1].max"
};

} // namespace airtrap
