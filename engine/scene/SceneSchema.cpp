#include "scene/SceneSchema.h"

#include "core/Error.h"
#include "scene/ClosestKey.h"
#include "scene/SceneSections.h"

#include <charconv>

namespace airtrap {

const std::vector<SchemaSection>& SceneSchema::sections() {
    // A constant table, built on first use; nothing ever modifies it.
    static const std::vector<SchemaSection> sections = buildSceneSections();
    return sections;
}

const SchemaSection* SceneSchema::findSection(std::string_view key) {
    for (const SchemaSection& section : sections())
        if (section.key == key)
            return &section;
    return nullptr;
}

const ParameterDeclaration& SceneSchema::formatVersion() {
    static const ParameterDeclaration declaration{
        .key = "format_version",
        .label = "Format version",
        .kind = ParameterKind::Int,
        .minimum = 1, // the oldest version that can still be migrated
        .maximum = Scene::kFormatVersion,
        .defaultValue = static_cast<long long>(Scene::kFormatVersion),
        .help = "Version of the file format; required. Older versions are migrated on load, "
                "newer ones refused.",
    };
    return declaration;
}

std::string SceneSchema::pathOf(const SchemaSection& section, std::size_t element,
                                const std::string& key) {
    if (section.key.empty())
        return key;
    std::string path = section.key;
    if (section.isArray)
        path += '[' + std::to_string(element) + ']';
    return path + '.' + key;
}

std::vector<std::string> SceneSchema::topLevelKeys() {
    std::vector<std::string> keys{formatVersion().key};
    for (const std::string& key : sections().front().keys())
        keys.push_back(key);
    for (const SchemaSection& section : sections())
        if (!section.key.empty())
            keys.push_back(section.key);
    return keys;
}

namespace {

[[noreturn]] void badPath(const std::string& source, const std::string& message) {
    throw Error(ErrorKind::InvalidScene, source + ": " + message);
}

//! Every path one can set, at the level of sections: "name, seed, solver.<key>, …".
std::vector<std::string> settableRoots() {
    std::vector<std::string> roots = SceneSchema::sections().front().keys();
    for (const SchemaSection& section : SceneSchema::sections())
        if (!section.key.empty())
            roots.push_back(section.key + (section.isArray ? "[i]" : "") + ".<key>");
    return roots;
}

[[noreturn]] void unknownRoot(std::string_view name, const std::string& source) {
    std::vector<std::string> candidates;
    for (const SchemaSection& section : SceneSchema::sections())
        for (const std::string& key :
             section.key.empty() ? section.keys() : std::vector<std::string>{section.key})
            candidates.push_back(key);
    const std::string suggestion = closestKey(name, candidates);
    badPath(source,
            std::string(name) + ": unknown key" +
                (suggestion.empty() ? "; valid" : "; did you mean \"" + suggestion + "\"? Valid") +
                " keys: " + joinKeys(settableRoots()));
}

ParameterPath resolveTopLevel(std::string_view path, const std::string& source) {
    const SchemaSection& top = SceneSchema::sections().front();
    if (const BoundParameter* parameter = top.find(path))
        return {&top, parameter, 0, std::string(path)};
    const SchemaSection* section = SceneSchema::findSection(path);
    if (section == nullptr || path.empty())
        unknownRoot(path, source);
    badPath(source,
            std::string(path) + " is a section; set one of its keys, e.g. " +
                SceneSchema::pathOf(*section, 0, section->parameters.front().declaration.key));
}

//! Splits "fluid_blocks[2]" into name and index; `indexed` tells whether brackets were there.
std::string_view splitIndex(std::string_view head, std::size_t& element, bool& indexed,
                            std::string_view path, const std::string& source) {
    const auto bracket = head.find('[');
    indexed = bracket != std::string_view::npos;
    if (!indexed)
        return head;
    const std::string_view digits = head.substr(bracket + 1, head.size() - bracket - 2);
    const auto parsed = std::from_chars(digits.data(), digits.data() + digits.size(), element);
    if (head.back() != ']' || digits.empty() || parsed.ec != std::errc() ||
        parsed.ptr != digits.data() + digits.size())
        badPath(source, "malformed path " + std::string(path) +
                            "; expected section[index].key, e.g. fluid_blocks[0].max");
    return head.substr(0, bracket);
}

} // namespace

ParameterPath SceneSchema::resolve(std::string_view path, const std::string& source) {
    const auto dot = path.find('.');
    if (dot == std::string_view::npos)
        return resolveTopLevel(path, source);
    std::size_t element = 0;
    bool indexed = false;
    const std::string_view name = splitIndex(path.substr(0, dot), element, indexed, path, source);
    const std::string key(path.substr(dot + 1));
    const SchemaSection* section = findSection(name);
    if (section == nullptr || name.empty())
        unknownRoot(name, source);
    if (section->isArray && !indexed)
        badPath(source, std::string(name) + " is a list; address one element, e.g. " +
                            std::string(name) + "[0]." + key);
    if (!section->isArray && indexed)
        badPath(source,
                std::string(name) + " is not a list; write " + std::string(name) + "." + key);
    const BoundParameter* parameter = section->find(key);
    if (parameter == nullptr)
        badPath(source, unknownKeyMessage(pathOf(*section, element, key), key, section->keys(),
                                          "of " + section->key));
    return {section, parameter, element, pathOf(*section, element, key)};
}

} // namespace airtrap
