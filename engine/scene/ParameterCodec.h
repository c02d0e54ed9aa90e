#pragma once
// Converts parameter values from and to JSON and command-line text, checking them against their
// declaration. The JSON reader, `--set` and the editor share it, so they accept the same values
// and word their messages the same way.
#include "scene/ParameterDeclaration.h"

#include <nlohmann/json.hpp>
#include <string>

namespace airtrap {

class ParameterCodec {
public:
    //! A converted value, or the reason it was refused (then `value` is meaningless).
    struct Result {
        ParameterValue value;
        std::string error;
        bool ok() const { return error.empty(); }
    };

    //! Converts `json` to the declared kind and checks its range. `path` ("solver.fps") starts
    //! the error, which reads "<path>: expected <expectation>, got <json>" for a wrong type and
    //! "<path> = <value> is out of range; expected <expectation>" for a bad value.
    static Result fromJson(const ParameterDeclaration& declaration, const nlohmann::json& json,
                           const std::string& path);

    //! Same for command-line text: a JSON literal ("0.02", "[1,2,0.5]", "\"a b\""), bare text for
    //! strings and choices ("box"), or comma-separated numbers for vectors ("1,2,0.5").
    static Result fromText(const ParameterDeclaration& declaration, const std::string& text,
                           const std::string& path);

    //! Checks the range (or choice, or string length) of a value of the declared kind. Returns
    //! the error as fromJson words it, or an empty string when the value is allowed.
    static std::string check(const ParameterDeclaration& declaration, const ParameterValue& value,
                             const std::string& path);

    static nlohmann::json toJson(const ParameterValue& value);

    //! What a valid value looks like: "a number in [0.001, 1] m", "one of \"box\"".
    static std::string expectation(const ParameterDeclaration& declaration);
    //! The allowed range alone: "[0.001, 1]", "(0, 1000]", "1–200 characters", "\"box\"".
    static std::string rangeText(const ParameterDeclaration& declaration);
    //! Short type name for tables: "number", "integer", "[x, y, z]", "string", "choice", "bool".
    static std::string typeName(ParameterKind kind);

    //! A value as a user would type it: 0.02, 30, [0, -9.81, 0], "Water", true.
    static std::string formatValue(const ParameterValue& value);
    //! Shortest text that reads back to the same double; integers without a decimal point.
    static std::string formatNumber(double number);
    //! A JSON value for a one-line message: a pasted megabyte is cut to its start.
    static std::string shortJson(const nlohmann::json& json);
    //! The text without leading and trailing blanks (spaces, tabs).
    static std::string trimmed(const std::string& text);
};

} // namespace airtrap
