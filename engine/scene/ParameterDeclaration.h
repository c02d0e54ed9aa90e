#pragma once
// One scene parameter, declared once: its JSON key, label, unit, range, default and help. The JSON
// reader and validator, `--set`, docs/SCENE_FORMAT.md and the editor's parameter panel all read
// this declaration instead of keeping their own copy, so a rename or a new range cannot miss one.
#include "core/Math.h"

#include <string>
#include <variant>
#include <vector>

namespace airtrap {

//! The type of a parameter's value, which decides its JSON form and its editor widget.
enum class ParameterKind {
    Bool,    //!< JSON true/false
    Int,     //!< JSON integer; range in minimum..maximum
    Real,    //!< JSON number; range in minimum..maximum
    Vector3, //!< JSON [x, y, z]; the range applies to each component
    String,  //!< JSON string; minimum..maximum bound its length in characters
    Choice,  //!< JSON string, one of `choices` (enumerations are strings, never integers)
};

//! A parameter's value. Int is held as long long, Choice as std::string.
using ParameterValue = std::variant<bool, long long, double, Vec3d, std::string>;

struct ParameterDeclaration {
    std::string key{};   //!< JSON key, snake_case
    std::string label{}; //!< shown in the editor, e.g. "Particle spacing"
    std::string unit{};  //!< SI unit ("m", "m/s", "kg/m³"), empty when dimensionless
    ParameterKind kind = ParameterKind::Real;
    double minimum = 0.0; //!< inclusive unless minimumExclusive
    double maximum = 0.0; //!< inclusive unless maximumExclusive
    bool minimumExclusive = false;
    bool maximumExclusive = false;
    ParameterValue defaultValue{};      //!< taken when the key is missing from a scene file
    std::string help{};                 //!< one sentence, used as tooltip and in the docs
    std::vector<std::string> choices{}; //!< the allowed strings of a Choice parameter
    //! The parameter means something only while the Choice parameter `appliesWhenKey` of the
    //! same section or element has one of `appliesWhenValues` (a sphere's radius, not a box's):
    //! the editor shows it only then. Empty: always.
    std::string appliesWhenKey{};
    std::vector<std::string> appliesWhenValues{};
};

} // namespace airtrap
