#include "scene/ParameterCodec.h"

#include <charconv>
#include <cmath>
#include <cstddef>

namespace airtrap {
namespace {

using Json = nlohmann::json;
using Result = ParameterCodec::Result;

Result typeError(const ParameterDeclaration& declaration, const Json& json,
                 const std::string& path) {
    return {{},
            path + ": expected " + ParameterCodec::expectation(declaration) + ", got " +
                ParameterCodec::shortJson(json)};
}

bool inRange(const ParameterDeclaration& declaration, double number) {
    // Written so that NaN is out of range.
    const bool aboveMinimum =
        declaration.minimumExclusive ? number > declaration.minimum : number >= declaration.minimum;
    const bool belowMaximum =
        declaration.maximumExclusive ? number < declaration.maximum : number <= declaration.maximum;
    return aboveMinimum && belowMaximum;
}

//! Counts UTF-8 code points, so that "kg/m³"-style names are measured as a user sees them.
std::size_t characterCount(const std::string& text) {
    std::size_t count = 0;
    for (const char c : text)
        if ((static_cast<unsigned char>(c) & 0xC0) != 0x80)
            ++count;
    return count;
}

std::string quoted(const std::string& text) {
    return Json(text).dump();
}

std::string quotedList(const std::vector<std::string>& choices) {
    std::string text;
    for (const std::string& choice : choices)
        text += (text.empty() ? "" : ", ") + quoted(choice);
    return text;
}

bool valueAllowed(const ParameterDeclaration& declaration, const ParameterValue& value) {
    switch (declaration.kind) {
    case ParameterKind::Bool:
        return true;
    case ParameterKind::Int:
        return inRange(declaration, static_cast<double>(std::get<long long>(value)));
    case ParameterKind::Real:
        return inRange(declaration, std::get<double>(value));
    case ParameterKind::Vector3: {
        const Vec3d& vector = std::get<Vec3d>(value);
        return inRange(declaration, vector.x()) && inRange(declaration, vector.y()) &&
               inRange(declaration, vector.z());
    }
    case ParameterKind::String:
        return inRange(declaration,
                       static_cast<double>(characterCount(std::get<std::string>(value))));
    case ParameterKind::Choice:
        for (const std::string& choice : declaration.choices)
            if (choice == std::get<std::string>(value))
                return true;
        return false;
    }
    return false;
}

//! The variant alternative each kind is held in.
bool holdsKind(ParameterKind kind, const ParameterValue& value) {
    switch (kind) {
    case ParameterKind::Bool:
        return std::holds_alternative<bool>(value);
    case ParameterKind::Int:
        return std::holds_alternative<long long>(value);
    case ParameterKind::Real:
        return std::holds_alternative<double>(value);
    case ParameterKind::Vector3:
        return std::holds_alternative<Vec3d>(value);
    case ParameterKind::String:
    case ParameterKind::Choice:
        return std::holds_alternative<std::string>(value);
    }
    return false;
}

Result intFromJson(const ParameterDeclaration& declaration, const Json& json,
                   const std::string& path) {
    if (!json.is_number())
        return typeError(declaration, json, path);
    // A float that is a whole number (30.0) is accepted, as a hand-edited file may say so.
    const double number = json.get<double>();
    if (json.is_number_float() && number != std::floor(number))
        return typeError(declaration, json, path);
    // Checked as a double first: an integer beyond long long must not wrap into range.
    if (!inRange(declaration, number))
        return {{},
                path + " = " + ParameterCodec::shortJson(json) + " is out of range; expected " +
                    ParameterCodec::expectation(declaration)};
    const long long value = json.is_number_float() ? std::llround(number) : json.get<long long>();
    return {value, ParameterCodec::check(declaration, value, path)};
}

Result vectorFromJson(const ParameterDeclaration& declaration, const Json& json,
                      const std::string& path) {
    if (!json.is_array() || json.size() != 3)
        return typeError(declaration, json, path);
    Vec3d vector;
    for (int axis = 0; axis < 3; ++axis) {
        if (!json[static_cast<std::size_t>(axis)].is_number())
            return typeError(declaration, json, path);
        vector[axis] = json[static_cast<std::size_t>(axis)].get<double>();
    }
    return {vector, ParameterCodec::check(declaration, vector, path)};
}

Result convertJson(const ParameterDeclaration& declaration, const Json& json,
                   const std::string& path) {
    switch (declaration.kind) {
    case ParameterKind::Bool:
        if (!json.is_boolean())
            return typeError(declaration, json, path);
        return {json.get<bool>(), {}};
    case ParameterKind::Int:
        return intFromJson(declaration, json, path);
    case ParameterKind::Real:
        if (!json.is_number())
            return typeError(declaration, json, path);
        return {json.get<double>(), ParameterCodec::check(declaration, json.get<double>(), path)};
    case ParameterKind::Vector3:
        return vectorFromJson(declaration, json, path);
    case ParameterKind::String:
    case ParameterKind::Choice:
        if (!json.is_string())
            return typeError(declaration, json, path);
        return {json.get<std::string>(),
                ParameterCodec::check(declaration, json.get<std::string>(), path)};
    }
    return typeError(declaration, json, path);
}

} // namespace

Result ParameterCodec::fromJson(const ParameterDeclaration& declaration, const Json& json,
                                const std::string& path) {
    return convertJson(declaration, json, path);
}

Result ParameterCodec::fromText(const ParameterDeclaration& declaration, const std::string& text,
                                const std::string& path) {
    const std::string value = ParameterCodec::trimmed(text);
    Json json = Json::parse(value, nullptr, /*allow_exceptions=*/false);
    const bool isText =
        declaration.kind == ParameterKind::String || declaration.kind == ParameterKind::Choice;
    // Bare words are what people type for names and choices; `name=123` means the string too.
    if (isText && !json.is_string())
        json = value;
    else if (declaration.kind == ParameterKind::Vector3 && json.is_discarded())
        json = Json::parse("[" + value + "]", nullptr, false);
    if (json.is_discarded())
        json = value; // reported as "got \"abc\""
    return convertJson(declaration, json, path);
}

std::string ParameterCodec::check(const ParameterDeclaration& declaration,
                                  const ParameterValue& value, const std::string& path) {
    if (!holdsKind(declaration.kind, value))
        return path + ": expected " + expectation(declaration) + ", got " + formatValue(value);
    if (valueAllowed(declaration, value))
        return {};
    const char* problem = declaration.kind == ParameterKind::Choice ? " is not one of the choices"
                                                                    : " is out of range";
    return path + " = " + formatValue(value) + problem + "; expected " + expectation(declaration);
}

Json ParameterCodec::toJson(const ParameterValue& value) {
    return std::visit(
        [](const auto& held) -> Json {
            if constexpr (std::is_same_v<std::decay_t<decltype(held)>, Vec3d>)
                return Json::array({held.x(), held.y(), held.z()});
            else
                return Json(held);
        },
        value);
}

std::string ParameterCodec::expectation(const ParameterDeclaration& declaration) {
    const std::string unit = declaration.unit.empty() ? "" : " " + declaration.unit;
    const std::string range = rangeText(declaration);
    switch (declaration.kind) {
    case ParameterKind::Bool:
        return "true or false";
    case ParameterKind::Int:
        return "an integer in " + range + unit;
    case ParameterKind::Real:
        return "a number in " + range + unit;
    case ParameterKind::Vector3:
        return "an array of 3 numbers, each in " + range + unit;
    case ParameterKind::String:
        return "a string of " + range;
    case ParameterKind::Choice:
        return "one of " + range;
    }
    return {};
}

std::string ParameterCodec::rangeText(const ParameterDeclaration& declaration) {
    switch (declaration.kind) {
    case ParameterKind::Bool:
        return "true, false";
    case ParameterKind::String:
        return formatNumber(declaration.minimum) + " to " + formatNumber(declaration.maximum) +
               " characters";
    case ParameterKind::Choice:
        return quotedList(declaration.choices);
    default: {
        // Appended piece by piece: GCC 12 misreads `"(" + std::string` as an overlapping copy.
        std::string text(declaration.minimumExclusive ? "(" : "[");
        text += formatNumber(declaration.minimum);
        text += ", ";
        text += formatNumber(declaration.maximum);
        text += declaration.maximumExclusive ? ")" : "]";
        return text;
    }
    }
}

std::string ParameterCodec::typeName(ParameterKind kind) {
    switch (kind) {
    case ParameterKind::Bool:
        return "bool";
    case ParameterKind::Int:
        return "integer";
    case ParameterKind::Real:
        return "number";
    case ParameterKind::Vector3:
        return "[x, y, z]";
    case ParameterKind::String:
        return "string";
    case ParameterKind::Choice:
        return "choice";
    }
    return {};
}

std::string ParameterCodec::formatValue(const ParameterValue& value) {
    if (const auto* flag = std::get_if<bool>(&value))
        return *flag ? "true" : "false";
    if (const auto* integer = std::get_if<long long>(&value))
        return std::to_string(*integer);
    if (const auto* number = std::get_if<double>(&value))
        return formatNumber(*number);
    if (const auto* vector = std::get_if<Vec3d>(&value)) {
        std::string text("[");
        for (int axis = 0; axis < 3; ++axis)
            text += (axis == 0 ? "" : ", ") + formatNumber((*vector)[axis]);
        return text + "]";
    }
    return quoted(std::get<std::string>(value));
}

std::string ParameterCodec::formatNumber(double number) {
    // Whole numbers up to 2^53 print exactly, without the exponent that to_chars might choose
    // for 100000 ("1e+05").
    constexpr double kExactIntegers = 9007199254740992.0;
    if (std::isfinite(number) && number == std::floor(number) &&
        std::fabs(number) <= kExactIntegers)
        return std::to_string(static_cast<long long>(number));
    char buffer[64];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, number).ptr;
    return std::string(buffer, end);
}

std::string ParameterCodec::shortJson(const Json& json) {
    constexpr std::size_t kMaxLength = 60;
    std::string text = json.dump();
    if (text.size() > kMaxLength)
        text = text.substr(0, kMaxLength) + "…";
    return text;
}

std::string ParameterCodec::trimmed(const std::string& text) {
    const auto first = text.find_first_not_of(" \t");
    if (first == std::string::npos)
        return {};
    return text.substr(first, text.find_last_not_of(" \t") - first + 1);
}

} // namespace airtrap
