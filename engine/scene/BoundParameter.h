#pragma once
// A parameter declaration bound to the field of a Scene it describes.
#include "scene/ParameterDeclaration.h"
#include "scene/Scene.h"

#include <any>
#include <cstddef>
#include <functional>

namespace airtrap {

struct BoundParameter {
    ParameterDeclaration declaration;

    //! Reads the field. `element` selects the fluid block or obstacle in an array section and is
    //! ignored elsewhere; it must be below SchemaSection::elementCount().
    std::function<ParameterValue(const Scene& scene, std::size_t element)> get;

    //! Writes the field without range checks (ParameterCodec::check does those). Int and Real
    //! values are converted into each other; any other kind mismatch throws
    //! Error(InvalidInput).
    std::function<void(Scene& scene, std::size_t element, const ParameterValue& value)> set;

    //! The bound field as a pointer to member (`&SolverSettings::maxSpeed`), so that code can
    //! name a parameter by its field and get its key from here (SceneSchema::keyOf); empty for
    //! a parameter bound to no field.
    std::any field{};
};

} // namespace airtrap
