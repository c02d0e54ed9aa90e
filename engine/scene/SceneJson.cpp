#include "scene/SceneJson.h"

#include "core/AtomicFile.h"
#include "core/Error.h"
#include "scene/ClosestKey.h"
#include "scene/ParameterCodec.h"
#include "scene/SceneMigration.h"
#include "scene/SceneSchema.h"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <cstdio>
#include <map>
#include <regex>

namespace airtrap {
namespace {

using Json = nlohmann::json;
using OrderedJson = nlohmann::ordered_json;

//! Reads a scene through the schema, collecting every problem rather than stopping at the first,
//! so that one round of editing fixes a file.
class SceneReader {
public:
    explicit SceneReader(std::string sourceName) : source_(std::move(sourceName)) {}

    Scene read(const Json& root) {
        Scene scene;
        checkKeys(root, SceneSchema::topLevelKeys(), SceneSchema::sections().front(), 0,
                  "at the top level");
        for (const SchemaSection& section : SceneSchema::sections())
            readSection(section, root, scene);
        if (!errors_.empty())
            throw Error(ErrorKind::InvalidScene, joined());
        scene.sourcePath = source_;
        return scene;
    }

private:
    void error(const std::string& message) { errors_.push_back(source_ + ": " + message); }

    std::string joined() const {
        std::string text;
        for (const std::string& line : errors_)
            text += (text.empty() ? "" : "\n") + line;
        return text;
    }

    void readSection(const SchemaSection& section, const Json& root, Scene& scene) {
        if (section.key.empty())
            return readValues(section, root, 0, scene);
        const Json missing = section.isArray ? Json::array() : Json::object();
        const Json& value = root.contains(section.key) ? root[section.key] : missing;
        if (section.isArray)
            readArray(section, value, scene);
        else if (!value.is_object())
            error(section.key + ": expected an object, got " + ParameterCodec::shortJson(value));
        else
            readObject(section, value, 0, scene);
    }

    void readArray(const SchemaSection& section, const Json& array, Scene& scene) {
        if (!array.is_array())
            return error(section.key + ": expected an array of objects, got " +
                         ParameterCodec::shortJson(array));
        section.resize(scene, array.size());
        for (std::size_t element = 0; element < array.size(); ++element) {
            if (array[element].is_object())
                readObject(section, array[element], element, scene);
            else
                error(section.key + "[" + std::to_string(element) + "]: expected an object, got " +
                      ParameterCodec::shortJson(array[element]));
        }
    }

    void readObject(const SchemaSection& section, const Json& object, std::size_t element,
                    Scene& scene) {
        checkKeys(object, section.keys(), section, element, "of " + section.key);
        readValues(section, object, element, scene);
    }

    //! Sets every declared parameter: from the JSON when present, else its declared default.
    void readValues(const SchemaSection& section, const Json& object, std::size_t element,
                    Scene& scene) {
        for (const BoundParameter& parameter : section.parameters) {
            const ParameterDeclaration& declaration = parameter.declaration;
            if (!object.contains(declaration.key)) {
                parameter.set(scene, element, declaration.defaultValue);
                continue;
            }
            const std::string path = SceneSchema::pathOf(section, element, declaration.key);
            const auto result =
                ParameterCodec::fromJson(declaration, object[declaration.key], path);
            if (result.ok())
                parameter.set(scene, element, result.value);
            else
                error(result.error);
        }
    }

    void checkKeys(const Json& object, const std::vector<std::string>& validKeys,
                   const SchemaSection& section, std::size_t element, const std::string& where) {
        for (const auto& item : object.items())
            if (std::find(validKeys.begin(), validKeys.end(), item.key()) == validKeys.end())
                error(unknownKeyMessage(SceneSchema::pathOf(section, element, item.key()),
                                        item.key(), validKeys, where));
    }

    std::string source_;
    std::vector<std::string> errors_;
};

//! "line 3, column 5: syntax error …" out of nlohmann's "[json.exception.parse_error.101] parse
//! error at line 3, column 5: syntax error …".
std::string parseErrorMessage(const Json::parse_error& error, const std::string& sourceName) {
    static const std::regex position("line ([0-9]+), column ([0-9]+): (.*)");
    std::smatch match;
    const std::string what = error.what();
    if (std::regex_search(what, match, position))
        return sourceName + ": malformed JSON at line " + match[1].str() + ", column " +
               match[2].str() + ": " + match[3].str();
    return sourceName + ": malformed JSON: " + what;
}

//! "line 3, column 5" of the `occurrence`-th (from 1) appearance of "key": as an object key
//! in `text`, or "" if it is not found as written (a key spelled with escapes).
std::string keyPosition(const std::string& text, const std::string& key, int occurrence) {
    const std::string quoted = "\"" + key + "\"";
    int seen = 0;
    for (std::size_t at = text.find(quoted); at != std::string::npos;
         at = text.find(quoted, at + 1)) {
        if (at > 0 && text[at - 1] == '\\')
            continue; // inside a string value, escaped
        std::size_t after = at + quoted.size();
        while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after])))
            ++after;
        if (after >= text.size() || text[after] != ':' || ++seen < occurrence)
            continue;
        const std::size_t lineStart = text.rfind('\n', at);
        const auto line = 1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n');
        const std::size_t column = at - (lineStart == std::string::npos ? 0 : lineStart + 1) + 1;
        return "line " + std::to_string(line) + ", column " + std::to_string(column);
    }
    return {};
}

//! Watches a parse for a key that appears twice in one object. nlohmann keeps the last value
//! silently, so a scene edited by hand could lose a setting without a word.
class DuplicateKeyWatch {
public:
    Json::parser_callback_t callback() {
        return [this](int, Json::parse_event_t event, Json& parsed) {
            if (event == Json::parse_event_t::object_start)
                objects_.emplace_back();
            else if (event == Json::parse_event_t::object_end && !objects_.empty())
                objects_.pop_back();
            else if (event == Json::parse_event_t::key)
                noteKey(parsed.get<std::string>());
            return true;
        };
    }
    bool found() const { return !key_.empty(); }
    std::string message(const std::string& text, const std::string& sourceName) const {
        const std::string first = keyPosition(text, key_, firstOccurrence_);
        const std::string second = keyPosition(text, key_, secondOccurrence_);
        std::string where;
        if (!first.empty() && !second.empty())
            where = ", at " + first + " and " + second;
        return sourceName + ": key \"" + key_ + "\" appears twice in the same object" + where +
               "; expected each key once (the second would silently replace the first)";
    }

private:
    void noteKey(const std::string& key) {
        const int occurrence = ++occurrences_[key];
        if (objects_.empty() || found())
            return;
        const auto [it, fresh] = objects_.back().emplace(key, occurrence);
        if (!fresh) {
            key_ = key;
            firstOccurrence_ = it->second;
            secondOccurrence_ = occurrence;
        }
    }

    std::vector<std::map<std::string, int>> objects_; //!< per open object: key → occurrence
    std::map<std::string, int> occurrences_;          //!< of each key text, in the whole file
    std::string key_;                                 //!< the first duplicate found
    int firstOccurrence_ = 0;
    int secondOccurrence_ = 0;
};

//! "<file>: malformed JSON at line 4, column 17: the number 1e999 is too large for a double …"
//! out of nlohmann's "[json.exception.out_of_range.406] number overflow parsing '1e999'", which
//! has no position: the number is found in the text.
std::string overflowMessage(const Json::out_of_range& error, const std::string& text,
                            const std::string& sourceName) {
    static const std::regex quoted("'([^']+)'");
    std::smatch match;
    const std::string what = error.what();
    if (!std::regex_search(what, match, quoted))
        return sourceName + ": malformed JSON: " + what;
    const std::string number = match[1].str();
    std::string where;
    if (const std::size_t at = text.find(number); at != std::string::npos) {
        const std::size_t lineStart = text.rfind('\n', at);
        const auto line = 1 + std::count(text.begin(), text.begin() + std::ptrdiff_t(at), '\n');
        const std::size_t column = at - (lineStart == std::string::npos ? 0 : lineStart + 1) + 1;
        where = " at line " + std::to_string(line) + ", column " + std::to_string(column);
    }
    return sourceName + ": malformed JSON" + where + ": the number " + number +
           " is too large for a double, expected a magnitude below 1.8e308";
}

template <class JsonType>
JsonType sectionObject(const SchemaSection& section, const Scene& scene, std::size_t element) {
    JsonType object = JsonType::object();
    for (const BoundParameter& parameter : section.parameters)
        object[parameter.declaration.key] =
            JsonType(ParameterCodec::toJson(parameter.get(scene, element)));
    return object;
}

template <class JsonType>
JsonType toJson(const Scene& scene) {
    JsonType root = JsonType::object();
    root[SceneSchema::formatVersion().key] = Scene::kFormatVersion;
    for (const SchemaSection& section : SceneSchema::sections()) {
        if (section.key.empty()) {
            root.update(sectionObject<JsonType>(section, scene, 0));
        } else if (section.isArray) {
            JsonType array = JsonType::array();
            for (std::size_t element = 0; element < section.elementCount(scene); ++element)
                array.push_back(sectionObject<JsonType>(section, scene, element));
            root[section.key] = std::move(array);
        } else {
            root[section.key] = sectionObject<JsonType>(section, scene, 0);
        }
    }
    return root;
}

bool isFlat(const OrderedJson& array) {
    for (const OrderedJson& item : array)
        if (item.is_structured())
            return false;
    return true;
}

//! Like dump(4), but arrays of plain values stay on one line: "min": [0.0, 0.0, 0.0].
void format(const OrderedJson& json, int depth, std::string& out) {
    const std::string indent(static_cast<std::size_t>(4 * (depth + 1)), ' ');
    const std::string closingIndent(static_cast<std::size_t>(4 * depth), ' ');
    if (!json.is_structured() || json.empty()) {
        out += json.dump();
    } else if (json.is_array() && isFlat(json)) {
        out += "[";
        for (std::size_t i = 0; i < json.size(); ++i)
            out += (i == 0 ? "" : ", ") + json[i].dump();
        out += "]";
    } else {
        out += json.is_object() ? "{\n" : "[\n";
        std::size_t remaining = json.size();
        for (const auto& item : json.items()) {
            out += indent;
            if (json.is_object())
                out += OrderedJson(item.key()).dump() + ": ";
            format(item.value(), depth + 1, out);
            out += --remaining > 0 ? ",\n" : "\n";
        }
        out += closingIndent + (json.is_object() ? "}" : "]");
    }
}

std::uint64_t fnv1a64(const std::string& bytes) {
    std::uint64_t hash = 0xcbf29ce484222325ULL;
    for (const char byte : bytes) {
        hash ^= static_cast<unsigned char>(byte);
        hash *= 0x100000001b3ULL;
    }
    return hash;
}

} // namespace

Scene readSceneFile(const std::string& path) {
    const std::vector<std::uint8_t> bytes = AtomicFile::read(path);
    return sceneFromText(std::string(bytes.begin(), bytes.end()), path);
}

Scene sceneFromText(const std::string& text, const std::string& sourceName) {
    Json json;
    try {
        DuplicateKeyWatch duplicates;
        json = Json::parse(text, duplicates.callback());
        if (duplicates.found())
            throw Error(ErrorKind::InvalidScene, duplicates.message(text, sourceName));
    } catch (const Json::parse_error& error) {
        throw Error(ErrorKind::InvalidScene, parseErrorMessage(error, sourceName));
    } catch (const Json::out_of_range& error) {
        throw Error(ErrorKind::InvalidScene, overflowMessage(error, text, sourceName));
    }
    return sceneFromJson(json, sourceName);
}

Scene sceneFromJson(const Json& json, const std::string& sourceName) {
    if (!json.is_object())
        throw Error(ErrorKind::InvalidScene, sourceName +
                                                 ": expected a JSON object at the top level, got " +
                                                 ParameterCodec::shortJson(json));
    return SceneReader(sourceName).read(SceneMigration::toCurrent(json, sourceName));
}

Json sceneToJson(const Scene& scene) {
    return toJson<Json>(scene);
}

OrderedJson sceneToOrderedJson(const Scene& scene) {
    return toJson<OrderedJson>(scene);
}

std::string sceneToText(const Scene& scene) {
    std::string text;
    format(sceneToOrderedJson(scene), 0, text);
    return text + "\n";
}

void writeSceneFile(const Scene& scene, const std::string& path) {
    AtomicFile::write(path, sceneToText(scene));
}

std::string parameterHash(const Scene& scene) {
    Json canonical = sceneToJson(scene);
    // The name is a label, and the end frame only says how far to bake: renaming a scene or
    // extending its bake must not orphan its cache. Nor must a change to how it is rendered.
    canonical.erase("name");
    canonical["frames"].erase("end_frame");
    // The render outputs' settings shape the post stage only; the bake does not read them.
    for (const SchemaSection& section : SceneSchema::sections())
        if (section.renderSetting)
            canonical.erase(section.key);
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx",
                  static_cast<unsigned long long>(fnv1a64(canonical.dump())));
    return hex;
}

} // namespace airtrap
