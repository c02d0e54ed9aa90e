#pragma once
// Scene files: JSON with `format_version`, read and written through the declarations of
// SceneSchema. Reading checks every field (type, range, choice, unknown keys); cross-field checks
// are SceneValidator's, which bake and validate run next.
#include "scene/Scene.h"

#include <nlohmann/json.hpp>
#include <string>

namespace airtrap {

//! Reads and checks a scene file; Scene::sourcePath is set to `path`. Throws Error(Io) when the
//! file cannot be read and Error(InvalidScene) when it is malformed: every problem on its own line,
//! each naming the file, the JSON path, the value and the allowed range.
Scene readSceneFile(const std::string& path);

//! Parses and checks scene text; `sourceName` starts every message (a path, "clipboard").
//! Malformed JSON is reported with its line and column.
Scene sceneFromText(const std::string& text, const std::string& sourceName);

//! Checks and converts a parsed scene: missing keys take their declared defaults, unknown keys
//! are errors (with a "did you mean"), older format versions are migrated, newer ones refused.
Scene sceneFromJson(const nlohmann::json& json, const std::string& sourceName);

//! The scene as JSON, every declared key present (sorted keys: the canonical form).
nlohmann::json sceneToJson(const Scene& scene);

//! The same, with keys in declaration order, as files are written.
nlohmann::ordered_json sceneToOrderedJson(const Scene& scene);

//! The file text: declaration order, 4-space indent, vectors on one line, final newline.
std::string sceneToText(const Scene& scene);

//! Writes the scene atomically (temporary file, fsync, rename), so that a crash leaves either the
//! old file or the new one. Throws Error(Io) naming `path`.
void writeSceneFile(const Scene& scene, const std::string& path);

//! 16 hex digits of FNV-1a 64 over the canonical JSON without the top-level `name`: equal for
//! scenes that simulate the same, so a frame cache can tell whether it belongs to a scene.
std::string parameterHash(const Scene& scene);

} // namespace airtrap
