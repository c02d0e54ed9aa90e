#include "document/BodyTemplate.h"

#include "scene/ParameterCodec.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

namespace airtrap {

namespace {

constexpr double kShareOfContainer = 0.2;
constexpr double kMinSpacings = 4.0;
//! A long file name makes an unwieldy tree row; the name is cut to this many characters.
constexpr std::size_t kMaxStemLength = 48;

nlohmann::json toJson(const Vec3d& value) {
    return ParameterCodec::toJson(ParameterValue(value));
}

bool nameTaken(const Scene& scene, const std::string& name) {
    return std::any_of(scene.bodies.begin(), scene.bodies.end(),
                       [&](const RigidBodySettings& body) { return body.name == name; });
}

std::string capitalised(std::string word) {
    if (!word.empty())
        word[0] = char(std::toupper(static_cast<unsigned char>(word[0])));
    return word;
}

} // namespace

double BodyTemplate::defaultExtent(const Scene& scene) {
    const double smallestSide = (scene.container.max - scene.container.min).minCoeff();
    const double extent =
        std::max(kShareOfContainer * smallestSide, kMinSpacings * scene.solver.particleSpacing);
    // A container too small for four spacings still gets a body that fits in it.
    return std::min(extent, 0.8 * smallestSide);
}

Vec3d BodyTemplate::placement(const Scene& scene, double height) {
    const ContainerSettings& container = scene.container;
    Vec3d position = 0.5 * (container.min + container.max);
    double waterTop = container.min.y();
    for (const FluidBlock& block : scene.fluidBlocks)
        waterTop = std::max(waterTop, std::min(block.max.y(), container.max.y()));
    const double half = 0.5 * height;
    position.y() = waterTop + scene.solver.particleSpacing + half;
    // Above the rim is still inside the domain, but a body there is easily missed.
    position.y() =
        std::max(container.min.y() + half, std::min(position.y(), container.max.y() - half));
    return position;
}

std::string BodyTemplate::uniqueName(const Scene& scene, const std::string& base) {
    if (!nameTaken(scene, base))
        return base;
    for (int number = 2;; ++number) {
        const std::string name = base + " " + std::to_string(number);
        if (!nameTaken(scene, name))
            return name;
    }
}

nlohmann::json BodyTemplate::primitive(const Scene& scene, const std::string& shape) {
    const double extent = defaultExtent(scene);
    nlohmann::json body = nlohmann::json::object();
    body["name"] = uniqueName(scene, capitalised(shape));
    body["shape"] = shape;
    body["size"] = toJson(Vec3d::Constant(extent));
    body["radius"] = 0.5 * extent;
    body["height"] = extent;
    body["position"] = toJson(placement(scene, extent));
    return body;
}

nlohmann::json BodyTemplate::mesh(const Scene& scene, const std::string& reference,
                                  const TriangleMesh& mesh) {
    const Aabb bounds = mesh.bounds();
    const Vec3d centre = bounds.center();
    const double height = bounds.size().y();
    nlohmann::json body = nlohmann::json::object();
    std::string stem = std::filesystem::path(reference).stem().string().substr(0, kMaxStemLength);
    body["name"] = uniqueName(scene, stem.empty() ? std::string("Mesh") : stem);
    body["shape"] = "mesh";
    body["mesh"] = reference;
    // The body's position is where the mesh's own origin goes: shift it so the bounds' centre
    // lands on the spot.
    body["position"] = toJson(placement(scene, height) - centre);
    return body;
}

} // namespace airtrap
