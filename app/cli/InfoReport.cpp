#include "InfoReport.h"

#include "cache/FrameFile.h"
#include "scene/SceneJson.h"
#include "sim/SceneSetup.h"

#include <cstdio>
#include <limits>

namespace airtrap::cli {

namespace {

nlohmann::ordered_json vector(const Vec3f& v) {
    return {double(v.x()), double(v.y()), double(v.z())};
}

//! In full double precision, as the state keeps it (`vector` above rounds to float).
nlohmann::ordered_json preciseVector(const Vec3d& v) {
    return {v.x(), v.y(), v.z()};
}

//! {"age": n, "floating": n, "overlap": n, "impact": n}
nlohmann::ordered_json perRule(const BubbleTally& tally) {
    nlohmann::ordered_json counts = nlohmann::ordered_json::object();
    for (int rule = 0; rule < BubbleTally::RuleCount; ++rule)
        counts[std::string(BubbleTally::kRuleNames[rule])] = tally.deleted[rule];
    return counts;
}

//! "age 2, floating 10, overlap 5, impact 1"
std::string perRuleText(const BubbleTally& tally) {
    std::string text;
    for (int rule = 0; rule < BubbleTally::RuleCount; ++rule)
        text += (rule > 0 ? ", " : "") + std::string(BubbleTally::kRuleNames[rule]) + " " +
                std::to_string(tally.deleted[rule]);
    return text;
}

//! [[min x, y, z], [max x, y, z]] of the particle positions; null when there are none.
nlohmann::ordered_json bounds(const ParticleSet& fluid) {
    if (fluid.empty())
        return nullptr;
    Vec3f low = Vec3f::Constant(std::numeric_limits<float>::infinity());
    Vec3f high = -low;
    for (const Vec3f& p : fluid.positions) {
        low = low.cwiseMin(p);
        high = high.cwiseMax(p);
    }
    return {vector(low), vector(high)};
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

} // namespace

InfoReport::InfoReport(const FrameData& frame, const CacheManifest& manifest, std::string directory)
    : frame_(frame), manifest_(manifest), directory_(std::move(directory)) {}

nlohmann::ordered_json InfoReport::fluidJson() const {
    return {{"count", frame_.state.fluid.size()},
            {"bounds", bounds(frame_.state.fluid)},
            {"max_speed", frame_.stats.maxSpeed},
            {"mean_density", frame_.stats.meanDensity}};
}

nlohmann::ordered_json InfoReport::timingJson() const {
    nlohmann::ordered_json timing = {{"wall_seconds", frame_.stats.wallSeconds}};
    for (const auto& [phase, seconds] : frame_.stats.phaseSeconds)
        timing[phase] = seconds;
    return timing;
}

nlohmann::ordered_json InfoReport::cacheJson() const {
    nlohmann::ordered_json frames = nlohmann::ordered_json::array();
    for (const CacheFrameEntry& entry : manifest_.frames)
        frames.push_back(entry.frame);
    return {{"directory", directory_},
            {"frames", frames},
            {"status", manifest_.status},
            {"parameter_hash", manifest_.parameterHash},
            {"fps", manifest_.fps}};
}

nlohmann::ordered_json InfoReport::bodiesJson() const {
    // The container and obstacles never move: their poses come from the scene the cache was
    // baked from, built as the solver builds them. The scene's bodies are where the frame has
    // them.
    const Scene scene = sceneFromJson(manifest_.scene, directory_ + "/manifest.json");
    std::vector<RigidBody> bodies = SceneSetup::buildBodies(scene);
    const std::size_t scenery = SceneSetup::sceneryCount(scene);
    const std::vector<RigidBodyState>& states = frame_.state.bodies;
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (std::size_t k = 0; k < bodies.size(); ++k) {
        RigidBody& body = bodies[k];
        if (k >= scenery && k - scenery < states.size())
            body.setState(states[k - scenery]);
        const Quatd& q = body.orientation();
        nlohmann::ordered_json entry = {
            {"name", body.name()},
            {"motion", RigidBody::motionName(body.motion())},
            {"position", vector(body.position().cast<float>())},
            {"orientation", {q.w(), q.x(), q.y(), q.z()}},
            {"linear_velocity", vector(body.linearVelocity().cast<float>())},
            {"angular_velocity", vector(body.angularVelocity().cast<float>())}};
        if (body.isDynamic()) {
            entry["mass"] = body.inertia().mass();
            entry["centre_of_mass_offset"] = vector(body.shapeOffset().cast<float>());
        }
        list.push_back(std::move(entry));
    }
    return list;
}

nlohmann::ordered_json InfoReport::bubblesJson() const {
    const SimulationState& state = frame_.state;
    nlohmann::ordered_json items = nlohmann::ordered_json::array();
    for (const BubbleState& bubble : state.bubbles)
        items.push_back({{"id", bubble.id},
                         {"center", preciseVector(bubble.body.position)},
                         {"radius", bubble.radius},
                         {"velocity", preciseVector(bubble.body.linearVelocity)},
                         {"age", bubble.age}});
    return {{"count", state.bubbles.size()},
            {"created_total", state.nextBubbleId},
            {"deleted_total", perRule(state.bubblesDeleted)},
            {"created_in_frame", frame_.stats.bubbles.created},
            {"deleted_in_frame", perRule(frame_.stats.bubbles)},
            {"items", items}};
}

nlohmann::ordered_json InfoReport::pressureSolveJson() const {
    const PressureSolveStats& solve = frame_.stats.pressureSolve;
    return {{"steps", solve.steps},
            {"divergence_iterations_per_step", solve.meanIterations(solve.divergenceIterations)},
            {"density_iterations_per_step", solve.meanIterations(solve.densityIterations)},
            {"mean_density_error", solve.meanDensityError},
            {"max_density_error", solve.maxDensityError},
            {"unconverged_steps", solve.unconvergedSteps}};
}

nlohmann::ordered_json InfoReport::toJson() const {
    nlohmann::ordered_json json = {{"frame", frame_.state.frame}, {"time", frame_.state.time},
                                   {"steps", frame_.state.steps}, {"fluid", fluidJson()},
                                   {"bodies", bodiesJson()},      {"bubbles", bubblesJson()},
                                   {"timing", timingJson()}};
    // Frames of divergence-free bakes only.
    if (frame_.stats.pressureSolve.steps > 0)
        json["pressure_solve"] = pressureSolveJson();
    json["cache"] = cacheJson();
    // What the frame holds without its wall-clock statistics: equal for two bakes that computed
    // the same state, e.g. a farm's requeued bake and an undisturbed one (docs/FARM.md).
    const std::vector<std::uint8_t> state = encodeFrame(frame_.state, FrameStats{});
    json["state_crc32"] = computeCrc32(state.data(), state.size());
    return json;
}

void InfoReport::printText(std::ostream& out) const {
    const SimulationState& state = frame_.state;
    out << "cache   " << directory_ << " (" << manifest_.frames.size() << " frames, status "
        << manifest_.status << ")\n";
    out << "frame   " << state.frame << "  t = " << fixed(state.time, 4) << " s  " << state.steps
        << " steps\n";
    out << "water   " << state.fluid.size() << " particles, max speed "
        << fixed(frame_.stats.maxSpeed, 3) << " m/s, mean density "
        << fixed(frame_.stats.meanDensity, 2) << " kg/m³\n";
    const nlohmann::ordered_json box = bounds(state.fluid);
    if (!box.is_null()) {
        out << "bounds ";
        for (const auto& corner : box)
            out << " (" << fixed(corner[0], 3) << ", " << fixed(corner[1], 3) << ", "
                << fixed(corner[2], 3) << ")";
        out << " m\n";
    }
    if (state.nextBubbleId > 0 || state.bubblesDeleted.deletedTotal() > 0)
        out << "bubbles " << state.bubbles.size() << " alive, " << state.nextBubbleId
            << " created, " << state.bubblesDeleted.deletedTotal() << " deleted ("
            << perRuleText(state.bubblesDeleted) << ")\n";
    const PressureSolveStats& solve = frame_.stats.pressureSolve;
    if (solve.steps > 0)
        out << "solver  DFSPH, " << solve.steps << " steps, iterations per step "
            << fixed(solve.meanIterations(solve.divergenceIterations), 1) << " (divergence) "
            << fixed(solve.meanIterations(solve.densityIterations), 1)
            << " (density), density error " << fixed(100.0 * solve.meanDensityError, 4)
            << " % mean, " << fixed(100.0 * solve.maxDensityError, 4) << " % max\n";
    out << "timing  " << fixed(frame_.stats.wallSeconds, 3) << " s wall";
    for (const auto& [phase, seconds] : frame_.stats.phaseSeconds)
        out << ", " << phase << " " << fixed(seconds, 3) << " s";
    out << '\n';
}

} // namespace airtrap::cli
