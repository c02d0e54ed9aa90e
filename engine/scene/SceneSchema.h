#pragma once
// The one declaration of every scene parameter, grouped in sections. Read by the JSON reader and
// writer (SceneJson), `--set` (SceneOverride), docs/SCENE_FORMAT.md (SceneFormatDoc) and the
// editor's parameter panel, which builds its widgets by iterating sections() and calls the
// parameters' get/set with ParameterValue.
#include "scene/ParameterPath.h"
#include "scene/SchemaSection.h"

#include <string>
#include <string_view>
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

    //! Every JSON key allowed at the top level of a scene file, format_version included.
    static std::vector<std::string> topLevelKeys();
};

} // namespace airtrap
