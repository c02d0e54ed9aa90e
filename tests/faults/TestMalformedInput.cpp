// The malformed-input corpus: one row per rule the scene reader, the validator and the cache
// readers enforce, each with the exit code and a fragment of the message it must give
// (docs/SCENE_FORMAT.md "Validation", docs/CACHE_FORMAT.md "What a reader checks", docs/CLI.md
// "Exit codes"). Scenes: a row for every declared parameter given a value outside its range or
// of the wrong kind, built from the declarations, and a row for every structural and cross-field
// rule. Caches: a fresh bake and post, damaged at test time in every file kind, every position
// and every way (a flipped byte, cut short, emptied, deleted, a newer version with its own
// checksums made to hold); `check` must name the damage, and the documented way on must bring
// back exactly what the undisturbed run made.
#include "faults/FaultTestSupport.h"
#include "fuzz/FuzzInput.h"
#include "scene/SceneSchema.h"
#include "support/TestMain.h"

#include <QTemporaryDir>
#include <map>
#include <sys/stat.h>

using namespace airtrap;
using namespace airtrap::faulttest;

namespace {

//! A valid scene with one element in every array section, so that every parameter of the
//! schema has a place in it. Small enough to validate in milliseconds.
nlohmann::json corpusScene() {
    return nlohmann::json::parse(R"({
        "format_version": 1,
        "name": "Corpus",
        "solver": {"particle_spacing": 0.04, "max_speed": 2.0},
        "frames": {"fps": 60.0, "end_frame": 4},
        "container": {"min": [0, 0, 0], "max": [0.6, 0.4, 0.6], "headroom": 0.2},
        "fluid_blocks": [{"name": "Water", "min": [0, 0, 0], "max": [0.2, 0.2, 0.2]}],
        "obstacles": [{"name": "Post", "center": [0.5, 0.1, 0.5], "size": [0.08, 0.2, 0.08]}],
        "emitters": [{"name": "Inflow", "position": [0.3, 0.5, 0.3], "direction": [0, -1, 0],
                      "radius": 0.04, "speed": 1.0, "stop_time": 0.05, "max_particles": 200}],
        "bodies": [{"name": "Paddle", "motion": "kinematic", "position": [0.45, 0.3, 0.15],
                    "size": [0.08, 0.08, 0.08]}],
        "keyframes": [{"body": "Paddle", "time": 0, "position": [0.45, 0.3, 0.15]},
                      {"body": "Paddle", "time": 1, "position": [0.45, 0.3, 0.3]}],
        "bubbles": {"enabled": true}
    })");
}

//! One row: what to write, what to run, and how it must end.
struct InputCase {
    std::string name;
    //! Writes the input into the case folder and returns the command that reads it.
    std::function<QStringList(const std::string& dir)> prepare;
    int exitCode;
    //! Each must appear in stderr or stdout; "{dir}" stands for the case folder.
    std::vector<std::string> fragments;
    //! For damaged caches: the documented way on, run after the command; each must succeed and
    //! leave the cache intact and equal to the undisturbed one.
    std::vector<QStringList> repair = {};
    bool damagedCache = false;
};

std::vector<InputCase>& corpus() {
    static std::vector<InputCase> cases;
    return cases;
}

// ---- Scenes ----------------------------------------------------------------------------------

//! The row of a scene `edit` makes from the corpus scene, validated with `airtrap-cli validate`.
InputCase sceneCase(std::string name, std::function<void(nlohmann::json&)> edit, int exitCode,
                    std::vector<std::string> fragments) {
    auto prepare = [edit = std::move(edit)](const std::string& dir) {
        nlohmann::json scene = corpusScene();
        edit(scene);
        writeText(dir + "/scene.json", scene.dump(2));
        return args({"validate", dir + "/scene.json"});
    };
    return {std::move(name), prepare, exitCode, std::move(fragments)};
}

//! The row of a scene file holding exactly `text`.
InputCase textCase(std::string name, std::string text, int exitCode,
                   std::vector<std::string> fragments) {
    auto prepare = [text = std::move(text)](const std::string& dir) {
        writeText(dir + "/scene.json", text);
        return args({"validate", dir + "/scene.json"});
    };
    return {std::move(name), prepare, exitCode, std::move(fragments)};
}

//! Where a parameter lives in the scene JSON.
nlohmann::json& slotOf(nlohmann::json& scene, const SchemaSection& section) {
    if (section.key.empty())
        return scene;
    if (section.isArray)
        return scene[section.key][0];
    return scene[section.key];
}

//! A value of the declared kind just outside the declared range, and the words the complaint
//! must use; for a bool, which has no range, a value of the wrong kind.
std::pair<nlohmann::json, std::string> outsideOf(const ParameterDeclaration& declared) {
    const auto beyond = [&]() -> double {
        if (declared.maximum < 1e15)
            return declared.maximumExclusive ? declared.maximum
                                             : declared.maximum + std::max(1.0, declared.maximum);
        return declared.minimumExclusive ? declared.minimum
                                         : declared.minimum - std::max(1.0, -declared.minimum);
    };
    switch (declared.kind) {
    case ParameterKind::Bool:
        return {"yes", "expected true or false"};
    case ParameterKind::Int:
        return {declared.maximum < 1e15 ? (long long)declared.maximum + 1
                                        : (long long)declared.minimum - 1,
                "is out of range"};
    case ParameterKind::Real:
        return {beyond(), "is out of range"};
    case ParameterKind::Vector3:
        return {nlohmann::json::array({beyond(), 0.1, 0.1}), "is out of range"};
    case ParameterKind::String:
        return {declared.minimum > 0 ? std::string()
                                     : std::string(std::size_t(declared.maximum) + 1, 'x'),
                "is out of range"};
    case ParameterKind::Choice:
        return {"no_such_choice", "is not one of the choices"};
    }
    return {};
}

//! One row per declared parameter: its value outside the declared range.
void addDeclaredRangeCases() {
    for (const SchemaSection& section : SceneSchema::sections())
        for (const BoundParameter& parameter : section.parameters) {
            const ParameterDeclaration& declared = parameter.declaration;
            if (declared.key == SceneSchema::formatVersion().key)
                continue; // a rule of its own below: newer files are refused by name
            const std::string path = SceneSchema::pathOf(section, 0, declared.key);
            const auto [value, complaint] = outsideOf(declared);
            corpus().push_back(
                sceneCase(path + " outside its range",
                          [&section, key = declared.key, value = value](nlohmann::json& scene) {
                              slotOf(scene, section)[key] = value;
                          },
                          2, {"{dir}/scene.json: " + path, complaint}));
        }
}

void addStructuralCases() {
    const std::string valid = corpusScene().dump(2);
    auto& rows = corpus();
    rows.push_back(textCase("empty file", "", 2, {"{dir}/scene.json", "line 1"}));
    rows.push_back(textCase("not an object", "[1, 2, 3]\n", 2, {"{dir}/scene.json", "object"}));
    rows.push_back(textCase("malformed JSON", "{\n  \"format_version\": 1,\n  \"name\" 3\n}\n", 2,
                            {"{dir}/scene.json", "line 3"}));
    rows.push_back(
        textCase("cut short", valid.substr(0, valid.size() / 2), 2, {"{dir}/scene.json", "line"}));
    rows.push_back(textCase("invalid UTF-8", "{\"format_version\": 1, \"name\": \"\xff\xfe\"}", 2,
                            {"{dir}/scene.json"}));
    rows.push_back(textCase(
        "duplicate key", "{\n  \"format_version\": 1,\n  \"name\": \"A\",\n  \"name\": \"B\"\n}\n",
        2, {"{dir}/scene.json", "name", "line 3", "line 4"}));
    rows.push_back(
        textCase("number beyond a double",
                 "{\n  \"format_version\": 1,\n  \"solver\": {\"max_speed\": 1e999}\n}\n", 2,
                 {"{dir}/scene.json", "line 3"}));
    rows.push_back(sceneCase("unknown key",
                             [](nlohmann::json& s) { s["solver"]["partcle_spacing"] = 0.04; }, 2,
                             {"partcle_spacing", "particle_spacing"}));
    rows.push_back(sceneCase("unknown section",
                             [](nlohmann::json& s) { s["solverr"] = nlohmann::json::object(); }, 2,
                             {"solverr", "solver"}));
    rows.push_back(sceneCase("no format_version",
                             [](nlohmann::json& s) { s.erase("format_version"); }, 2,
                             {"format_version"}));
    rows.push_back(sceneCase("newer format_version",
                             [](nlohmann::json& s) { s["format_version"] = 99; }, 2,
                             {"format_version", "99"}));
    rows.push_back(sceneCase("section of the wrong kind",
                             [](nlohmann::json& s) { s["solver"] = 3; }, 2, {"solver", "object"}));
    rows.push_back(
        sceneCase("array section given an object",
                  [](nlohmann::json& s) { s["fluid_blocks"] = nlohmann::json::object(); }, 2,
                  {"fluid_blocks", "array"}));
    rows.push_back(sceneCase("vector of two numbers",
                             [](nlohmann::json& s) {
                                 s["fluid_blocks"][0]["max"] = {0.2, 0.2};
                             },
                             2, {"fluid_blocks[0].max", "3 numbers"}));
    rows.push_back(sceneCase("null value",
                             [](nlohmann::json& s) { s["solver"]["max_speed"] = nullptr; }, 2,
                             {"solver.max_speed", "expected a number"}));
    rows.push_back(sceneCase("number given as text",
                             [](nlohmann::json& s) { s["solver"]["max_speed"] = "2"; }, 2,
                             {"solver.max_speed", "expected a number"}));
    rows.push_back(sceneCase("fraction for an integer",
                             [](nlohmann::json& s) { s["frames"]["end_frame"] = 4.5; }, 2,
                             {"frames.end_frame", "integer"}));
    // A scene that cannot be read at all is an I/O error, as docs/CLI.md lists it.
    rows.push_back({"missing scene file",
                    [](const std::string& dir) {
                        return args({"validate", dir + "/none.json"});
                    },
                    4,
                    {"cannot read {dir}/none.json: No such file"}});
    rows.push_back({"scene path is a folder",
                    [](const std::string& dir) {
                        fs::create_directories(dir + "/folder.json");
                        return args({"validate", dir + "/folder.json"});
                    },
                    4,
                    {"cannot read {dir}/folder.json: Is a directory"}});
}

//! The corpus scene's body, dynamic and without keyframes: its own position then places it.
void freeThePaddle(nlohmann::json& scene) {
    scene["bodies"][0]["motion"] = "dynamic";
    scene["keyframes"] = nlohmann::json::array();
}

void addCrossFieldCases() {
    auto& rows = corpus();
    const auto add = [&](std::string name, std::function<void(nlohmann::json&)> edit, int code,
                         std::vector<std::string> fragments) {
        rows.push_back(sceneCase(std::move(name), std::move(edit), code, std::move(fragments)));
    };
    add("inverted container",
        [](auto& s) {
            s["container"]["min"] = {0.7, 0, 0};
        },
        2, {"container.min.x = 0.7 must be less than container.max.x = 0.6"});
    add("no water",
        [](auto& s) {
            s["fluid_blocks"] = nlohmann::json::array();
            s["emitters"] = nlohmann::json::array();
        },
        2, {"a scene needs water"});
    add("inverted fluid block",
        [](auto& s) {
            s["fluid_blocks"][0]["min"] = {0.3, 0, 0};
        },
        2, {"fluid_blocks[0] (\"Water\"): min.x = 0.3 must be less than max.x = 0.2"});
    add("fluid block outside the domain",
        [](auto& s) {
            s["fluid_blocks"][0]["max"] = {0.2, 0.2, 0.9};
        },
        2, {"fluid_blocks[0] (\"Water\") reaches outside the domain", "max.z = 0.9 > 0.6"});
    add("obstacle outside the domain",
        [](auto& s) {
            s["obstacles"][0]["center"] = {0.59, 0.1, 0.5};
        },
        2, {"obstacles[0] (\"Post\") reaches outside the domain"});
    add("emitter stops before it starts", [](auto& s) { s["emitters"][0]["start_time"] = 0.1; }, 2,
        {"stop_time = 0.05 s must be later than start_time = 0.1 s"});
    add("emitter faster than max_speed", [](auto& s) { s["emitters"][0]["speed"] = 3.0; }, 2,
        {"emitters[0] (\"Inflow\"): speed = 3 m/s exceeds solver.max_speed = 2 m/s"});
    add("emitter without direction",
        [](auto& s) {
            s["emitters"][0]["direction"] = {0, 0, 0};
        },
        2, {"direction is zero"});
    add("emitter nozzle outside the domain",
        [](auto& s) {
            s["emitters"][0]["position"] = {0.59, 0.5, 0.3};
        },
        2, {"emitters[0] (\"Inflow\")'s nozzle reaches outside the domain"});
    add("too many particles",
        [](auto& s) {
            s["solver"]["particle_spacing"] = 0.001;
            s["fluid_blocks"][0]["max"] = {0.6, 0.4, 0.6};
        },
        2, {"million particles", "the limit is 20 million"});
    add("two bodies of one name", [](auto& s) { s["bodies"].push_back(s["bodies"][0]); }, 2,
        {"bodies[1] (\"Paddle\") has the name of bodies[0] (\"Paddle\")"});
    add("box body thinner than the spacing",
        [](auto& s) {
            s["bodies"][0]["size"] = {0.08, 0.01, 0.08};
        },
        2, {"bodies[0] (\"Paddle\").size = 0.01 m is less than solver.particle_spacing"});
    add("sphere body smaller than the spacing",
        [](auto& s) {
            s["bodies"][0]["shape"] = "sphere";
            s["bodies"][0]["radius"] = 0.01;
        },
        2, {"bodies[0] (\"Paddle\").radius = 0.01 m is less than solver.particle_spacing"});
    add("cylinder body shorter than the spacing",
        [](auto& s) {
            s["bodies"][0]["shape"] = "cylinder";
            s["bodies"][0]["height"] = 0.01;
        },
        2, {"bodies[0] (\"Paddle\").height = 0.01 m"});
    add("mesh body without a mesh", [](auto& s) { s["bodies"][0]["shape"] = "mesh"; }, 2,
        {"bodies[0] (\"Paddle\").mesh is empty"});
    add("body outside the domain",
        [](auto& s) {
            freeThePaddle(s);
            s["bodies"][0]["position"] = {0.59, 0.3, 0.15};
        },
        2, {"bodies[0] (\"Paddle\")", "domain"});
    add("sphere wider than the domain",
        [](auto& s) {
            s["bodies"][0]["shape"] = "sphere";
            s["bodies"][0]["radius"] = 5.06;
        },
        2, {"bodies[0] (\"Paddle\").radius: the sphere is 10.12 m across, larger than the domain"});
    add("keyframe of an unknown body", [](auto& s) { s["keyframes"][1]["body"] = "Nobody"; }, 2,
        {"keyframes[1]", "Nobody"});
    add("keyframe of a dynamic body", [](auto& s) { s["bodies"][0]["motion"] = "dynamic"; }, 2,
        {"keyframes[0]", "kinematic"});
    add("two keyframes at one time", [](auto& s) { s["keyframes"][1]["time"] = 0; }, 2,
        {"keyframes[1]", "time"});
    add("restitutions out of order",
        [](auto& s) {
            s["bubbles"]["approach_restitution"] = -0.1;
            s["bubbles"]["overlap_restitution"] = -0.5;
        },
        2, {"bubbles.approach_restitution = -0.1 exceeds bubbles.overlap_restitution = -0.5"});
    add("rise cap above max_speed", [](auto& s) { s["bubbles"]["max_rise_speed"] = 3.0; }, 2,
        {"bubbles.max_rise_speed = 3 m/s exceeds solver.max_speed = 2 m/s"});
    add("water starting faster than max_speed",
        [](auto& s) {
            s["fluid_blocks"][0]["initial_velocity"] = {3, 0, 0};
        },
        2, {"initial_velocity's speed is 3 m/s, above solver.max_speed = 2 m/s"});
    add("more minimum than maximum iterations",
        [](auto& s) {
            s["solver"]["min_iterations"] = 50;
            s["solver"]["max_iterations"] = 10;
        },
        2, {"solver.min_iterations = 50 exceeds solver.max_iterations = 10"});
    add("minimum time step above the maximum",
        [](auto& s) {
            s["solver"]["min_time_step"] = 0.01;
            s["solver"]["max_time_step"] = 0.001;
        },
        2, {"solver.min_time_step = 0.01 s exceeds solver.max_time_step = 0.001 s"});
    add("surface particle radius below 1.5 voxels",
        [](auto& s) {
            s["surface_mesh"]["voxel_size"] = 0.02;
            s["surface_mesh"]["particle_radius"] = 0.02;
        },
        2, {"surface_mesh.particle_radius"});
    add("sub-grid sizes out of order",
        [](auto& s) {
            s["subgrid_bubbles"]["min_size"] = 0.3;
            s["subgrid_bubbles"]["max_size"] = 0.2;
        },
        2, {"subgrid_bubbles.min_size = 0.3 exceeds subgrid_bubbles.max_size = 0.2"});
    // Warnings: the scene is valid (exit 0), and the warning says what will happen.
    add("overlapping fluid blocks (warning)",
        [](auto& s) {
            s["fluid_blocks"].push_back(s["fluid_blocks"][0]);
            s["fluid_blocks"][1]["name"] = "Second";
        },
        0, {"fluid_blocks[0] (\"Water\") overlaps fluid_blocks[1] (\"Second\")"});
    add("fluid block thinner than the spacing (warning)",
        [](auto& s) {
            s["fluid_blocks"][0]["max"] = {0.2, 0.02, 0.2};
        },
        0, {"is thinner than solver.particle_spacing"});
    add("fluid block not a whole number of spacings (warning)",
        [](auto& s) {
            s["fluid_blocks"][0]["max"] = {0.21, 0.2, 0.2};
        },
        0, {"not a whole number of solver.particle_spacing"});
    add("emitter budget below one layer (warning)",
        [](auto& s) { s["emitters"][0]["max_particles"] = 1; }, 0,
        {"max_particles = 1 is less than one layer"});
    // Placing a body in the water is how a scene floats one: a note, not a warning.
    add("body in the water (note)",
        [](auto& s) {
            freeThePaddle(s);
            s["bodies"][0]["position"] = {0.1, 0.1, 0.1};
        },
        0, {"note: ", "bodies[0] (\"Paddle\") starts in fluid_blocks[0]"});
}

//! Mesh bodies: the file a scene names, in every way it can be wrong.
void addMeshCases() {
    auto& rows = corpus();
    const auto meshCase = [&](std::string name, std::function<void(const std::string&)> make,
                              std::vector<std::string> fragments, double scale = 1.0) {
        rows.push_back({std::move(name),
                        [make, scale](const std::string& dir) {
                            make(dir + "/body.obj");
                            nlohmann::json scene = corpusScene();
                            scene["bodies"][0]["shape"] = "mesh";
                            scene["bodies"][0]["mesh"] = "body.obj";
                            scene["bodies"][0]["mesh_scale"] = scale;
                            writeText(dir + "/scene.json", scene.dump(2));
                            return args({"validate", dir + "/scene.json"});
                        },
                        2, std::move(fragments)});
    };
    const std::string cube = std::string(AIRTRAP_SOURCE_DIR) + "/tests/data/bunny_lowres.obj";
    meshCase("mesh file missing", [](const std::string&) {}, {"{dir}/body.obj"});
    meshCase("mesh path is a folder", [](const std::string& p) { fs::create_directories(p); },
             {"{dir}/body.obj", "not a regular file"});
    meshCase("mesh path is a FIFO", [](const std::string& p) { ::mkfifo(p.c_str(), 0600); },
             {"{dir}/body.obj", "not a regular file"});
    meshCase("mesh file of garbage", [](const std::string& p) { writeText(p, "v 1 2\nf 9 9 9\n"); },
             {"{dir}/body.obj"});
    meshCase("mesh file empty", [](const std::string& p) { writeText(p, ""); }, {"{dir}/body.obj"});
    meshCase(
        "mesh scaled beyond the domain", [cube](const std::string& p) { fs::copy_file(cube, p); },
        {"bodies[0] (\"Paddle\").mesh_scale: the mesh scaled by 1000", "larger than the domain"},
        1000.0);
}

// ---- Damaged caches --------------------------------------------------------------------------

enum class Damage { FlippedByte, CutShort, Emptied, Deleted, NewerVersion };

const std::map<Damage, std::string>& damageNames() {
    static const std::map<Damage, std::string> names = {{Damage::FlippedByte, "a flipped byte"},
                                                        {Damage::CutShort, "cut short"},
                                                        {Damage::Emptied, "emptied"},
                                                        {Damage::Deleted, "deleted"},
                                                        {Damage::NewerVersion, "a newer version"}};
    return names;
}

//! A file written by a newer Airtrap: its version raised, its own checksums made to hold.
void raiseVersion(const std::string& path) {
    if (path.ends_with(".json")) {
        nlohmann::json json = readJson(path);
        json["format_version"] = 99;
        writeText(path, json.dump(2) + "\n");
        return;
    }
    std::vector<std::uint8_t> bytes = readBytes(path);
    if (path.ends_with(".atf")) {
        fuzz::put(bytes, 4, std::uint32_t(99));
        fuzz::fixFrameChecksums(bytes);
    } else if (path.ends_with(".vdb")) {
        fuzz::put(bytes, 8, std::uint32_t(9999)); // OpenVDB's file version; no own checksum
    } else {
        fuzz::put(bytes, 4, std::uint32_t(99));
        fuzz::fixTrailingChecksum(bytes);
    }
    writeBytes(path, bytes);
}

//! Where a flipped byte goes: the middle of the file; in post's lists, the first quote from the
//! middle on. The middle of post.json falls among checksums whose digits change from run to run
//! (OpenVDB writes a random UUID into each volume), and a flipped digit there can leave valid
//! JSON that lists another number, which is a damaged result's case, not a damaged list's; a
//! flipped quote makes the list unreadable in every run.
std::size_t flippedByteOf(const std::string& path, const std::vector<std::uint8_t>& bytes) {
    const std::size_t middle = bytes.size() / 2;
    const std::string name = fs::path(path).filename().string();
    if (name != "post.json" && name != "subgrid.json")
        return middle;
    const auto quote = std::find(bytes.begin() + std::ptrdiff_t(middle), bytes.end(), '"');
    return quote == bytes.end() ? middle : std::size_t(quote - bytes.begin());
}

void applyDamage(const std::string& path, Damage damage) {
    std::vector<std::uint8_t> bytes = readBytes(path);
    switch (damage) {
    case Damage::FlippedByte:
        bytes.at(flippedByteOf(path, bytes)) ^= 0x10;
        writeBytes(path, bytes);
        break;
    case Damage::CutShort:
        bytes.resize(bytes.size() * 2 / 3);
        writeBytes(path, bytes);
        break;
    case Damage::Emptied:
        writeBytes(path, {});
        break;
    case Damage::Deleted:
        fs::remove(path);
        break;
    case Damage::NewerVersion:
        raiseVersion(path);
        break;
    }
}

//! The folders every cache row starts from: a scene, its undisturbed bake and post.
struct CacheReference {
    std::string scene;
    std::string cache;
};

CacheReference& cacheReference() {
    static CacheReference reference;
    return reference;
}

//! A cache row: the reference copied, `file` damaged, `check` run, then the way on.
void addCacheCase(const std::string& file, Damage damage, int exitCode,
                  std::vector<std::string> fragments, bool rebake) {
    const std::string name = file + ", " + damageNames().at(damage);
    auto prepare = [file, damage](const std::string& dir) {
        copyFolder(cacheReference().cache, dir + "/cache");
        applyDamage(dir + "/cache/" + file, damage);
        return args({"check", dir + "/cache"});
    };
    // The way on `check` names: bake again with the bake's own command line and --resume (it
    // keeps every frame before the first damaged one), then post, which remakes what is damaged
    // or made from a frame baked again.
    std::vector<QStringList> repair;
    if (rebake)
        repair.push_back(
            args({"bake", cacheReference().scene, "--out", "{dir}/cache", "--resume", "-q"}));
    repair.push_back(args({"post", "{dir}/cache", "-q"}));
    if (damage == Damage::NewerVersion && file == "manifest.json")
        repair.clear(); // a newer Airtrap's cache is left alone: only that Airtrap goes on
    corpus().push_back({name, prepare, exitCode, std::move(fragments), std::move(repair), true});
}

void addDamagedCacheCases() {
    const std::vector<Damage> every = {Damage::FlippedByte, Damage::CutShort, Damage::Emptied,
                                       Damage::Deleted, Damage::NewerVersion};
    for (const char* frame : {"frame_0001.atf", "frame_0002.atf", "frame_0004.atf"})
        for (const Damage damage : every)
            addCacheCase(frame, damage, 3,
                         {std::string("damaged: {dir}/cache/") + frame, "--resume"}, true);
    addCacheCase("manifest.json", Damage::FlippedByte, 3,
                 {"damaged: {dir}/cache/manifest.json: the scene it records", "--resume"}, true);
    addCacheCase("manifest.json", Damage::CutShort, 3,
                 {"{dir}/cache/manifest.json: not valid JSON"}, true);
    addCacheCase("manifest.json", Damage::Emptied, 3, {"{dir}/cache/manifest.json: not valid JSON"},
                 true);
    addCacheCase(
        "manifest.json", Damage::Deleted, 2,
        {"{dir}/cache/manifest.json missing, though the folder holds frame files", "--resume"},
        true);
    addCacheCase("manifest.json", Damage::NewerVersion, 3,
                 {"{dir}/cache/manifest.json: written by a newer Airtrap"}, true);
    for (const char* list : {"post/post.json", "post/subgrid.json"})
        for (const Damage damage : every) {
            // A lost list loses nothing listed: check notes the unlisted files and exits 0.
            const bool lost = damage == Damage::Deleted;
            addCacheCase(list, damage, lost ? 0 : 3,
                         {std::string(lost ? "note: " : "damaged: ") + "{dir}/cache/" + list,
                          "airtrap-cli post"},
                         false);
        }
    for (const char* result :
         {"post/water_0002.atm", "post/fluid_0003.vdb", "post/subgrid_0004.atb"})
        for (const Damage damage : every)
            addCacheCase(result, damage, 3,
                         {std::string("damaged: {dir}/cache/") + result, "airtrap-cli post"},
                         false);
}

void buildCorpus() {
    corpus().clear();
    addDeclaredRangeCases();
    addStructuralCases();
    addCrossFieldCases();
    addMeshCases();
    addDamagedCacheCases();
}

std::string expanded(std::string text, const std::string& dir) {
    for (auto at = text.find("{dir}"); at != std::string::npos; at = text.find("{dir}"))
        text.replace(at, 5, dir);
    return text;
}

QStringList expanded(const QStringList& command, const std::string& dir) {
    QStringList result;
    for (const QString& word : command)
        result << QString::fromStdString(expanded(word.toStdString(), dir));
    return result;
}

} // namespace

class TestMalformedInput : public QObject {
    Q_OBJECT

    QTemporaryDir root_;

private Q_SLOTS:
    void initTestCase() {
        QVERIFY(root_.isValid());
        const std::string dir = root_.path().toStdString();
        CacheReference& reference = cacheReference();
        reference.scene = dir + "/bubbles.json";
        writeText(reference.scene, bubbleSceneText(4));
        reference.cache = dir + "/reference";
        QCOMPARE_EXIT(runCli(args({"bake", reference.scene, "--out", reference.cache, "-q"})), 0);
        QCOMPARE_EXIT(runCli(args({"post", reference.cache, "-q"})), 0);
    }

    void everyCaseEndsAsItsRowSays_data() {
        buildCorpus();
        QTest::addColumn<int>("row");
        for (std::size_t row = 0; row < corpus().size(); ++row)
            QTest::newRow(corpus()[row].name.c_str()) << int(row);
    }

    void everyCaseEndsAsItsRowSays() {
        QFETCH(int, row);
        const InputCase& input = corpus().at(std::size_t(row));
        const std::string dir = root_.path().toStdString() + "/case";
        fs::remove_all(dir);
        fs::create_directories(dir);
        const CliResult result = runCli(input.prepare(dir));
        QCOMPARE_EXIT(result, input.exitCode);
        const QString said = result.err + result.out;
        for (const std::string& fragment : input.fragments)
            QVERIFY_CONTAINS(said, expanded(fragment, dir));
        if (input.repair.empty())
            return; // nothing this build may repair
        for (const QStringList& command : input.repair)
            QCOMPARE_EXIT(runCli(expanded(command, dir)), 0);
        QCOMPARE_EXIT(runCli(args({"check", dir + "/cache"})), 0);
        QVERIFY_SAME_AS(dir + "/cache", cacheReference().cache);
    }

    //! The corpus is as large as the rules it stands for.
    void theCorpusCoversEveryRule() {
        buildCorpus();
        std::size_t scenes = 0;
        std::size_t caches = 0;
        for (const InputCase& input : corpus())
            (input.damagedCache ? caches : scenes) += 1;
        QVERIFY2(scenes >= 100, qPrintable(QString::number(scenes) + " scene cases"));
        QVERIFY2(caches >= 40, qPrintable(QString::number(caches) + " damaged caches"));
    }
};

AIRTRAP_TEST_GUILESS(TestMalformedInput)
#include "TestMalformedInput.moc"
