#pragma once
// A group of scene parameters: the top level, an object ("solver") or an array of objects
// ("fluid_blocks"). The editor builds one panel group per section.
#include "scene/BoundParameter.h"

#include <cstddef>
#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace airtrap {

struct SchemaSection {
    std::string key;   //!< JSON key of the section; empty for the top-level keys (name, seed)
    std::string label; //!< "Solver", "Fluid blocks"
    std::string help;  //!< one sentence for the docs and the panel header
    bool isArray = false;
    //! A render setting: read by the post stage and the exports only, so it may change after a
    //! bake (`--set` on post and export) and is left out of the cache's parameter hash.
    bool renderSetting = false;
    std::string elementLabel; //!< label of one array element ("Fluid block"); arrays only
    std::vector<BoundParameter> parameters;

    //! Number of elements in `scene` (1 for the top level and object sections).
    std::function<std::size_t(const Scene& scene)> elementCount;
    //! Resizes an array section, default-constructing new elements; no-op for other sections.
    std::function<void(Scene& scene, std::size_t count)> resize;
    //! Inserts a default-constructed element before `index` (≤ elementCount); arrays only.
    std::function<void(Scene& scene, std::size_t index)> insertDefault;
    //! Removes the element at `index` (< elementCount); arrays only.
    std::function<void(Scene& scene, std::size_t index)> erase;

    //! The parameter with this JSON key, or nullptr.
    const BoundParameter* find(std::string_view parameterKey) const {
        for (const BoundParameter& parameter : parameters)
            if (parameter.declaration.key == parameterKey)
                return &parameter;
        return nullptr;
    }

    //! The JSON keys of this section, in declaration order (for messages).
    std::vector<std::string> keys() const {
        std::vector<std::string> result;
        for (const BoundParameter& parameter : parameters)
            result.push_back(parameter.declaration.key);
        return result;
    }
};

} // namespace airtrap
