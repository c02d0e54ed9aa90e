#pragma once
// The one declaration of every scene parameter, grouped in sections. Read by the JSON reader and
// writer (SceneJson), `--set` (SceneOverride), docs/SCENE_FORMAT.md (SceneFormatDoc) and the
// editor's parameter panel, which builds its widgets by iterating sections() and calls the
// parameters' get/set with ParameterValue.
#include "scene/ParameterCodec.h"
#include "scene/ParameterPath.h"
#include "scene/SchemaSection.h"

#include <any>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace airtrap {

class SceneSchema {
public:
    //! All sections in file order: the top level (key ""), "solver", "frames", "container",
    //! "fluid_blocks", "obstacles". Built once; immutable.
    static const std::vector<SchemaSection>& sections();

    //! The section with this JSON key ("" for the top level), or nullptr.
    static const SchemaSection* findSection(std::string_view key);

    //! `format_version`: stored in every file, handled by SceneJson rather than bound to a field.
    static const ParameterDeclaration& formatVersion();

    //! Parses a dotted path: "name", "solver.particle_spacing", "fluid_blocks[1].max". Throws
    //! Error(InvalidScene) starting with `source` for a malformed path or unknown key, with a
    //! "did you mean" suggestion and the valid keys of that section. Does not check the element
    //! index against any scene.
    static ParameterPath resolve(std::string_view path, const std::string& source);

    //! "solver.fps", "fluid_blocks[2].min", "seed": the path of a parameter as messages print it.
    static std::string pathOf(const SchemaSection& section, std::size_t element,
                              const std::string& key);

    //! The dotted key of the parameter bound to `member` ("solver.max_speed" for
    //! &SolverSettings::maxSpeed; "fluid_blocks[2].min" with `element` 2 in an array section),
    //! for messages: the key comes from the declaration, so a rename reaches every message.
    template <class Owner, class Field>
    static std::string keyOf(Field Owner::*member, std::size_t element = 0) {
        const auto [section, parameter] = boundTo(member);
        return pathOf(*section, element, parameter->declaration.key);
    }
    //! The declaration's own key of the parameter bound to `member` ("stop_time"), for messages
    //! that name the element first ("emitters[0] (Inflow): stop_time = …").
    template <class Owner, class Field>
    static const std::string& nameOf(Field Owner::*member) {
        return boundTo(member).second->declaration.key;
    }

    //! Every JSON key allowed at the top level of a scene file, format_version included.
    static std::vector<std::string> topLevelKeys();

    //! The declared rule's complaint about the value `scene` holds in `member` (of `element` in
    //! an array section), worded as the JSON reader words it; empty when the value is allowed.
    //! For code below the reader that takes settings directly (post, tests).
    template <class Owner, class Field>
    static std::string check(const Scene& scene, Field Owner::*member, std::size_t element = 0) {
        const auto [section, parameter] = boundTo(member);
        return ParameterCodec::check(parameter->declaration, parameter->get(scene, element),
                                     pathOf(*section, element, parameter->declaration.key));
    }

    //! The declaration of the parameter bound to `member` (its range, unit, help), for messages
    //! that must not restate it.
    template <class Owner, class Field>
    static const ParameterDeclaration& declarationOf(Field Owner::*member) {
        return boundTo(member).second->declaration;
    }

private:
    //! The section and parameter bound to `member`. Throws std::logic_error for a field no
    //! parameter is bound to: a programming error, which TestSceneSchema's message tests catch.
    template <class Owner, class Field>
    static std::pair<const SchemaSection*, const BoundParameter*> boundTo(Field Owner::*member) {
        for (const SchemaSection& section : sections())
            for (const BoundParameter& parameter : section.parameters) {
                const auto* bound = std::any_cast<Field Owner::*>(&parameter.field);
                if (bound && *bound == member)
                    return {&section, &parameter};
            }
        throw std::logic_error("SceneSchema: the field is bound to no parameter");
    }
};

} // namespace airtrap
