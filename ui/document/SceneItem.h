#pragma once
// What a scene-tree row, a viewport gizmo and the parameter panel point at: a section of the scene
// ("solver"), the group of an array section ("fluid_blocks"), or one element of it
// ("fluid_blocks[1]"). Keys are those of SceneSchema, so an item needs no knowledge of the kinds
// of objects a scene holds; a new section appears in the tree, the panel and the picker for free.
#include <QMetaType>
#include <cstddef>
#include <string>

namespace airtrap {

struct SceneItem {
    enum class Kind {
        None,    //!< nothing selected
        Section, //!< an object section, or the top level (section "")
        Group,   //!< an array section as a whole
        Element, //!< one element of an array section
    };

    Kind kind = Kind::None;
    std::string section;     //!< SchemaSection::key
    std::size_t element = 0; //!< index of an Element; 0 otherwise

    static SceneItem none() { return {}; }
    static SceneItem sectionItem(std::string key) { return {Kind::Section, std::move(key), 0}; }
    static SceneItem group(std::string key) { return {Kind::Group, std::move(key), 0}; }
    static SceneItem elementItem(std::string key, std::size_t index) {
        return {Kind::Element, std::move(key), index};
    }

    //! Sections and elements have parameters to edit; groups and None do not.
    bool hasParameters() const { return kind == Kind::Section || kind == Kind::Element; }
    bool isNone() const { return kind == Kind::None; }

    bool operator==(const SceneItem& other) const = default;
};

} // namespace airtrap

Q_DECLARE_METATYPE(airtrap::SceneItem)
