#pragma once
// The machinery that binds a parameter declaration to its field in Scene: field access, the
// conversion between a field and a ParameterValue, and the builders of object and array sections.
// Shared by the files that declare the scene's sections (SceneSections.cpp, BodySections.cpp).
#include "core/Error.h"
#include "scene/ParameterCodec.h"
#include "scene/SchemaSection.h"

#include <cmath>
#include <cstdint>
#include <type_traits>

namespace airtrap::schema {

constexpr double kMaxCoordinate = 1000.0; //!< m; a kilometre is far beyond any sensible tank
constexpr double kMaxNameLength = 200.0;

// --- Field access: how a section reaches its plain-data object inside a Scene. -------------

struct TopLevelAccess {
    static Scene& of(Scene& scene, std::size_t) { return scene; }
    static const Scene& of(const Scene& scene, std::size_t) { return scene; }
};

template <auto Member>
struct ObjectAccess {
    static auto& of(Scene& scene, std::size_t) { return scene.*Member; }
    static const auto& of(const Scene& scene, std::size_t) { return scene.*Member; }
};

template <auto Member>
struct ElementAccess {
    static auto& of(Scene& scene, std::size_t element) { return (scene.*Member).at(element); }
    static const auto& of(const Scene& scene, std::size_t element) {
        return (scene.*Member).at(element);
    }
};

// --- Conversion between a field and a ParameterValue. ---------------------------------------

[[noreturn]] inline void kindMismatch(const std::string& key, const ParameterValue& value) {
    throw Error(ErrorKind::InvalidInput,
                "parameter " + key + " cannot hold " + ParameterCodec::formatValue(value));
}

inline double asReal(const ParameterValue& value, const std::string& key) {
    if (const auto* number = std::get_if<double>(&value))
        return *number;
    if (const auto* integer = std::get_if<long long>(&value))
        return static_cast<double>(*integer);
    kindMismatch(key, value);
}

// Spin boxes hand out doubles for integers too; rounding them is what the user meant.
inline long long asInteger(const ParameterValue& value, const std::string& key) {
    if (const auto* integer = std::get_if<long long>(&value))
        return *integer;
    if (const auto* number = std::get_if<double>(&value))
        return std::llround(*number);
    kindMismatch(key, value);
}

template <class Held>
const Held& asHeld(const ParameterValue& value, const std::string& key) {
    if (const auto* held = std::get_if<Held>(&value))
        return *held;
    kindMismatch(key, value);
}

inline ParameterValue toValue(bool field) {
    return field;
}
inline ParameterValue toValue(double field) {
    return field;
}
inline ParameterValue toValue(int field) {
    return static_cast<long long>(field);
}
inline ParameterValue toValue(std::uint64_t field) {
    return static_cast<long long>(field);
}
inline ParameterValue toValue(const Vec3d& field) {
    return field;
}
inline ParameterValue toValue(const std::string& field) {
    return field;
}

inline void assign(bool& field, const ParameterValue& value, const std::string& key) {
    field = asHeld<bool>(value, key);
}
inline void assign(double& field, const ParameterValue& value, const std::string& key) {
    field = asReal(value, key);
}
inline void assign(int& field, const ParameterValue& value, const std::string& key) {
    field = static_cast<int>(asInteger(value, key));
}
inline void assign(std::uint64_t& field, const ParameterValue& value, const std::string& key) {
    field = static_cast<std::uint64_t>(asInteger(value, key));
}
inline void assign(Vec3d& field, const ParameterValue& value, const std::string& key) {
    field = asHeld<Vec3d>(value, key);
}
inline void assign(std::string& field, const ParameterValue& value, const std::string& key) {
    field = asHeld<std::string>(value, key);
}

//! The kind follows from the field's type, so a declaration cannot disagree with its field; a
//! string field with declared choices is a Choice.
template <class Field>
ParameterKind kindOf(const ParameterDeclaration& declaration) {
    if constexpr (std::is_same_v<Field, std::string>)
        return declaration.choices.empty() ? ParameterKind::String : ParameterKind::Choice;
    else if constexpr (std::is_same_v<Field, bool>)
        return ParameterKind::Bool;
    else if constexpr (std::is_same_v<Field, double>)
        return ParameterKind::Real;
    else if constexpr (std::is_same_v<Field, Vec3d>)
        return ParameterKind::Vector3;
    else
        return ParameterKind::Int;
}

//! The declaration bound to `member`. Its default is the field's own in-class default
//! (scene/Scene.h): one place for every default, which the JSON reader, the docs and the editor
//! read from here.
template <class Access, class Owner, class Field>
BoundParameter bind(ParameterDeclaration declaration, Field Owner::*member) {
    declaration.kind = kindOf<Field>(declaration);
    declaration.defaultValue = toValue(Owner{}.*member);
    const std::string key = declaration.key;
    return {std::move(declaration),
            [member](const Scene& scene, std::size_t element) {
                return toValue(Access::of(scene, element).*member);
            },
            [member, key](Scene& scene, std::size_t element, const ParameterValue& value) {
                assign(Access::of(scene, element).*member, value, key);
            },
            member};
}

// --- The sections. ----------------------------------------------------------------------------

inline SchemaSection objectSection(std::string key, std::string label, std::string help,
                                   std::vector<BoundParameter> parameters) {
    SchemaSection section;
    section.key = std::move(key);
    section.label = std::move(label);
    section.help = std::move(help);
    section.parameters = std::move(parameters);
    section.elementCount = [](const Scene&) -> std::size_t { return 1; };
    section.resize = [](Scene&, std::size_t) {};
    section.insertDefault = [](Scene&, std::size_t) {};
    section.erase = [](Scene&, std::size_t) {};
    return section;
}

template <auto Member>
inline SchemaSection arraySection(std::string key, std::string label, std::string elementLabel,
                                  std::string help, std::vector<BoundParameter> parameters) {
    SchemaSection section =
        objectSection(std::move(key), std::move(label), std::move(help), std::move(parameters));
    section.isArray = true;
    section.elementLabel = std::move(elementLabel);
    section.elementCount = [](const Scene& scene) { return (scene.*Member).size(); };
    section.resize = [](Scene& scene, std::size_t count) { (scene.*Member).resize(count); };
    section.insertDefault = [](Scene& scene, std::size_t index) {
        auto& elements = scene.*Member;
        // An explicit value: `{}` would pick the initializer-list overload and insert nothing.
        using Element = typename std::remove_reference_t<decltype(elements)>::value_type;
        elements.insert(elements.begin() + static_cast<std::ptrdiff_t>(index), Element{});
    };
    section.erase = [](Scene& scene, std::size_t index) {
        auto& elements = scene.*Member;
        elements.erase(elements.begin() + static_cast<std::ptrdiff_t>(index));
    };
    return section;
}

} // namespace airtrap::schema
