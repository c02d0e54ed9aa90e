#include "sim/BodyBuilder.h"

#include "core/Error.h"
#include "rigid/EulerRotation.h"
#include "rigid/MeshLoader.h"
#include "rigid/ShapeSampler.h"
#include "rigid/SignedDistanceField.h"
#include "scene/ParameterCodec.h"
#include "sph/BoundaryVolumes.h"

#include <cstdio>
#include <filesystem>

namespace airtrap {
namespace {

//! Voxels of a mesh's distance field per particle spacing: contacts need the surface to a
//! fraction of a spacing.
constexpr double kVoxelsPerSpacing = 2.0;
//! Interior band of the field, in voxels: deep enough for any contact the solver resolves.
constexpr double kInteriorBandVoxels = 8.0;
//! Exterior band, in voxels (2.5 spacings). Beyond it the field reads the band's width, so it
//! must reach past what is asked of it: contacts look half a spacing out, and the air-pocket
//! search asks whether a body comes within half a grid cell's diagonal (√3 spacings) of a cell's
//! centre. With a narrower band every cell near a mesh body would look solid and no air could be
//! trapped next to one.
constexpr double kExteriorBandVoxels = 5.0;

std::string bodyLabel(const Scene& scene, const RigidBodySettings& body) {
    std::size_t index = 0;
    while (index < scene.bodies.size() && &scene.bodies[index] != &body)
        ++index;
    return (scene.sourcePath.empty() ? std::string("scene") : scene.sourcePath) + ": bodies[" +
           std::to_string(index) + "] (" + ParameterCodec::formatValue(body.name) + ")";
}

//! A length in metres to the centimetre, for messages.
std::string centimetres(double metres) {
    char text[64];
    std::snprintf(text, sizeof text, "%.2f", metres);
    return text;
}

//! Moves every particle `distance` along its normal.
void pushOut(BoundaryParticles& particles, double distance) {
    for (std::size_t k = 0; k < particles.size(); ++k)
        particles.positions[k] += static_cast<float>(distance) * particles.normals[k];
}

} // namespace

BodyBuilder::BodyBuilder(const Scene& scene, const CubicSplineKernel& kernel)
    : scene_(scene), kernel_(kernel), spacing_(scene.solver.particleSpacing) {}

std::string BodyBuilder::meshPath(const Scene& scene, const RigidBodySettings& body) {
    const std::filesystem::path file(body.mesh);
    if (file.is_absolute() || scene.sourcePath.empty())
        return file.string();
    return (std::filesystem::path(scene.sourcePath).parent_path() / file)
        .lexically_normal()
        .string();
}

Scene BodyBuilder::withAbsoluteMeshPaths(Scene scene) {
    for (RigidBodySettings& body : scene.bodies)
        if (!body.mesh.empty())
            body.mesh =
                std::filesystem::absolute(meshPath(scene, body)).lexically_normal().string();
    return scene;
}

TriangleMesh BodyBuilder::loadMesh(const Scene& scene, const RigidBodySettings& body) {
    if (body.mesh.empty())
        throw Error(ErrorKind::InvalidInput,
                    bodyLabel(scene, body) + ".mesh is empty; shape \"mesh\" needs a mesh file");
    TriangleMesh mesh;
    try {
        mesh = MeshLoader::load(meshPath(scene, body), body.meshScale);
    } catch (const Error& error) {
        throw Error(ErrorKind::InvalidInput, bodyLabel(scene, body) + ".mesh: " + error.what());
    }
    checkFitsTheDomain(scene, body, mesh);
    return mesh;
}

void BodyBuilder::checkFitsTheDomain(const Scene& scene, const RigidBodySettings& body,
                                     const TriangleMesh& mesh) {
    // The signed distance field and the boundary sampling that follow cost memory and time as
    // the body's size over the spacing, cubed: a mesh scaled far beyond the tank ran out of
    // memory before the placement check could say so. A body wider than the domain's diagonal
    // fits nowhere in it, whatever its pose.
    const double across = mesh.bounds().size().norm();
    const double diagonal = scene.domain().size().norm();
    if (across > diagonal)
        throw Error(ErrorKind::InvalidInput,
                    bodyLabel(scene, body) + ".mesh_scale: the mesh scaled by " +
                        ParameterCodec::formatNumber(body.meshScale) + " is " +
                        centimetres(across) +
                        " m across, larger than the domain (container plus headroom, " +
                        centimetres(diagonal) +
                        " m corner to corner); expected a mesh_scale that fits it inside");
}

BodyShape BodyBuilder::meshShape(const TriangleMesh& mesh, double spacing) {
    return BodyShape::mesh(std::make_shared<SignedDistanceField>(
        mesh, spacing / kVoxelsPerSpacing, kExteriorBandVoxels, kInteriorBandVoxels));
}

BodyShape BodyBuilder::shapeOf(const Scene& scene, const RigidBodySettings& body, double spacing) {
    if (body.shape == "sphere")
        return BodyShape::sphere(body.radius);
    if (body.shape == "cylinder")
        return BodyShape::cylinder(body.radius, body.height);
    if (body.shape == "mesh")
        return meshShape(loadMesh(scene, body), spacing);
    return BodyShape::box(body.size);
}

RigidBody BodyBuilder::build(std::size_t index) const {
    const RigidBodySettings& body = scene_.bodies.at(index);
    std::optional<TriangleMesh> mesh;
    if (body.shape == "mesh")
        mesh = loadMesh(scene_, body);
    BodyShape shape = mesh ? meshShape(*mesh, spacing_) : shapeOf(scene_, body, spacing_);
    const RigidPose pose{body.position, EulerRotation::fromDegrees(body.rotation)};
    RigidBody rigid(body.name, sampleBoundary(body, mesh ? &*mesh : nullptr), std::move(shape),
                    pose);
    rigid.setSurfaceOffset(0.5 * spacing_);
    const ContactMaterial material{body.restitution, body.friction};
    rigid.setMaterials(material, material);
    if (body.motion == "dynamic") {
        const MassProperties mass = massOf(body, mesh ? &*mesh : nullptr);
        rigid.makeDynamic(RigidBodyInertia(mass.mass, mass.inertia), mass.volume, mass.centreOfMass,
                          {body.linearVelocity, body.angularVelocity});
    } else if (body.motion == "kinematic") {
        rigid.makeKinematic(kinematicMotionOf(body));
    }
    return rigid;
}

BoundaryParticles BodyBuilder::sampleBoundary(const RigidBodySettings& body,
                                              const TriangleMesh* mesh) const {
    // Half a spacing inside the surface, as for the container's walls: the water particles
    // nearest the body rest one spacing from the layer, half a spacing outside the surface, so
    // the water's volume, and the buoyancy its pressure gives, ends at the true surface.
    const double half = 0.5 * spacing_;
    BoundaryParticles particles;
    if (body.shape == "sphere") {
        particles = ShapeSampler::sampleSphere(body.radius - half, spacing_);
    } else if (body.shape == "cylinder") {
        particles =
            ShapeSampler::sampleCylinder(body.radius - half, body.height - spacing_, spacing_);
    } else if (mesh) {
        particles = ShapeSampler::sampleMesh(*mesh, spacing_);
        pushOut(particles, -half);
    } else {
        particles = ShapeSampler::sampleSolidBox(body.size - Vec3d::Constant(spacing_), spacing_);
    }
    BoundaryVolumes::compute(particles, kernel_, spacing_);
    return particles;
}

MassProperties BodyBuilder::massOf(const RigidBodySettings& body, const TriangleMesh* mesh) const {
    if (body.shape == "sphere")
        return MassProperties::ofSphere(body.radius, body.density);
    if (body.shape == "cylinder")
        return MassProperties::ofCylinder(body.radius, body.height, body.density);
    if (mesh)
        return MassProperties::ofMesh(*mesh, body.density);
    return MassProperties::ofBox(body.size, body.density);
}

KinematicMotion BodyBuilder::kinematicMotionOf(const RigidBodySettings& body) const {
    std::vector<KeyframedPath::Keyframe> keys;
    for (const BodyKeyframe& key : scene_.keyframes)
        if (key.body == body.name)
            keys.push_back({key.time, key.position, EulerRotation::fromDegrees(key.rotation)});
    if (keys.empty())
        return KinematicMotion({body.position, EulerRotation::fromDegrees(body.rotation)},
                               {body.linearVelocity, body.angularVelocity});
    std::stable_sort(keys.begin(), keys.end(),
                     [](const auto& a, const auto& b) { return a.time < b.time; });
    try {
        return KinematicMotion(KeyframedPath(std::move(keys)));
    } catch (const Error& error) {
        throw Error(ErrorKind::InvalidInput,
                    bodyLabel(scene_, body) +
                        ": its keyframes do not form a path: " + error.what());
    }
}

} // namespace airtrap
