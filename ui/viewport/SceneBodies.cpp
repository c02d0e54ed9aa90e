#include "viewport/SceneBodies.h"

#include "rigid/EulerRotation.h"

#include <limits>

namespace airtrap {

namespace {

QMatrix4x4 matrixOf(const Vec3d& position, const Quatd& orientation) {
    const Mat3d rotation = orientation.normalized().toRotationMatrix();
    QMatrix4x4 matrix;
    for (int row = 0; row < 3; ++row) {
        for (int column = 0; column < 3; ++column)
            matrix(row, column) = float(rotation(row, column));
        matrix(row, 3) = float(position[row]);
    }
    return matrix;
}

} // namespace

SceneBodies::SceneBodies(const Scene& scene, BodyMeshCache& meshes) {
    for (std::size_t i = 0; i < scene.bodies.size(); ++i) {
        const RigidBodySettings& settings = scene.bodies[i];
        const BodyMeshCache::Entry shape = meshes.shapeOf(scene, settings);
        Body body;
        body.item = SceneItem::elementItem("bodies", i);
        body.motion = settings.motion;
        body.solid = shape.solid;
        body.centreOfMass = shape.centreOfMass;
        body.scenePose = scenePoseOf(scene, settings);
        body.pose = body.scenePose;
        body.boundingRadius = shape.solid ? shape.solid->boundingRadius() : 0.0f;
        bodies_.push_back(std::move(body));
    }
}

QMatrix4x4 SceneBodies::scenePoseOf(const Scene& scene, const RigidBodySettings& body) {
    // A keyframed body stands at its earliest keyframe until then (KeyframedPath holds it).
    const BodyKeyframe* first = nullptr;
    if (body.motion == "kinematic")
        for (const BodyKeyframe& keyframe : scene.keyframes)
            if (keyframe.body == body.name && (first == nullptr || keyframe.time < first->time))
                first = &keyframe;
    if (first != nullptr)
        return matrixOf(first->position, EulerRotation::fromDegrees(first->rotation));
    return matrixOf(body.position, EulerRotation::fromDegrees(body.rotation));
}

QMatrix4x4 SceneBodies::shapePose(const RigidBodyState& state, const std::string& motion,
                                  const Vec3d& centreOfMass) {
    const Vec3d origin = motion == "dynamic"
                             ? Vec3d(state.position - state.orientation * centreOfMass)
                             : state.position;
    return matrixOf(origin, state.orientation);
}

void SceneBodies::showStates(const std::vector<RigidBodyState>* states) {
    for (std::size_t i = 0; i < bodies_.size(); ++i) {
        Body& body = bodies_[i];
        body.pose = states != nullptr && i < states->size()
                        ? shapePose((*states)[i], body.motion, body.centreOfMass)
                        : body.scenePose;
    }
}

std::optional<PickHit> SceneBodies::pick(const Ray& ray) const {
    std::optional<PickHit> nearest;
    for (const Body& body : bodies_) {
        if (!body.solid)
            continue;
        // Cheap rejection first: the ray must pass within the solid's bounding sphere.
        const QVector3D centre = body.pose.map(QVector3D());
        const QVector3D toCentre = centre - ray.origin;
        const float along = QVector3D::dotProduct(toCentre, ray.direction);
        const float gapSquared = toCentre.lengthSquared() - along * along;
        if (gapSquared > body.boundingRadius * body.boundingRadius)
            continue;
        // The pose is rigid, so its inverse maps the ray into the shape frame unscaled.
        const QMatrix4x4 toShape = body.pose.inverted();
        const Ray local{toShape.map(ray.origin), toShape.mapVector(ray.direction).normalized()};
        const std::optional<float> distance = body.solid->hit(local);
        if (distance && (!nearest || *distance < nearest->distance))
            nearest = PickHit{body.item, *distance};
    }
    return nearest;
}

} // namespace airtrap
