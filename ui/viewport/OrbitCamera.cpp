#include "viewport/OrbitCamera.h"

#include <QtMath>
#include <algorithm>
#include <cmath>

namespace airtrap {

namespace {

constexpr float kMinDistance = 1e-3f;
constexpr float kMaxDistance = 1e5f;
constexpr float kMaxPitch = 89.0f;
//! Room left around a fitted box, as a share of the distance that would make it touch the edges.
constexpr float kFitMargin = 1.12f;

} // namespace

void OrbitCamera::setDistance(float metres) {
    distance_ = std::clamp(metres, kMinDistance, kMaxDistance);
}

void OrbitCamera::setAngles(float yawDegrees, float pitchDegrees) {
    yaw_ = std::fmod(yawDegrees, 360.0f);
    if (yaw_ < 0.0f) {
        yaw_ += 360.0f;
    }
    pitch_ = std::clamp(pitchDegrees, -kMaxPitch, kMaxPitch);
}

void OrbitCamera::setFieldOfView(float degrees) {
    fieldOfView_ = std::clamp(degrees, 5.0f, 120.0f);
}

QVector3D OrbitCamera::forward() const {
    const float yaw = qDegreesToRadians(yaw_);
    const float pitch = qDegreesToRadians(pitch_);
    // The eye sits at yaw/pitch on a sphere around the target; forward points back at the centre.
    const QVector3D towardsEye(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                               std::cos(pitch) * std::cos(yaw));
    return -towardsEye;
}

QVector3D OrbitCamera::right() const {
    return QVector3D::crossProduct(forward(), QVector3D(0.0f, 1.0f, 0.0f)).normalized();
}

QVector3D OrbitCamera::up() const {
    return QVector3D::crossProduct(right(), forward());
}

QMatrix4x4 OrbitCamera::viewMatrix() const {
    QMatrix4x4 view;
    view.lookAt(eye(), target_, up());
    return view;
}

float OrbitCamera::nearPlane() const {
    return std::max(distance_ * 0.01f, 1e-4f);
}

float OrbitCamera::farPlane() const {
    return 2.0f * distance_ + 4.0f * sceneRadius_;
}

QMatrix4x4 OrbitCamera::projectionMatrix(float aspectRatio) const {
    QMatrix4x4 projection;
    if (orthographic_) {
        const float halfHeight = orthographicHalfHeight();
        const float halfWidth = halfHeight * aspectRatio;
        // Parallel rays need no eye in front of the scene: zoomed in, the eye may sit inside it,
        // so the clip range reaches as far behind the eye as in front.
        projection.ortho(-halfWidth, halfWidth, -halfHeight, halfHeight, -farPlane(), farPlane());
    } else {
        projection.perspective(fieldOfView_, aspectRatio, nearPlane(), farPlane());
    }
    return projection;
}

float OrbitCamera::aspectOf(const QSize& size) {
    return size.height() > 0 ? float(size.width()) / float(size.height()) : 1.0f;
}

float OrbitCamera::tanHalfFieldOfView() const {
    return std::tan(qDegreesToRadians(fieldOfView_) * 0.5f);
}

Ray OrbitCamera::ray(const QPointF& pixel, const QSize& size) const {
    // Normalised device coordinates of the pixel, then the matching direction in the eye's frame.
    const float ndcX = float(2.0 * pixel.x() / std::max(size.width(), 1) - 1.0);
    const float ndcY = float(1.0 - 2.0 * pixel.y() / std::max(size.height(), 1));
    const float spread = tanHalfFieldOfView();
    if (orthographic_) {
        const float halfHeight = orthographicHalfHeight();
        const QVector3D onEyePlane =
            eye() + right() * (ndcX * halfHeight * aspectOf(size)) + up() * (ndcY * halfHeight);
        // Started behind the eye, as far as the clip range reaches: what is drawn can be picked.
        return {onEyePlane - forward() * farPlane(), forward()};
    }
    const QVector3D direction =
        forward() + right() * (ndcX * spread * aspectOf(size)) + up() * (ndcY * spread);
    return {eye(), direction.normalized()};
}

QVector3D OrbitCamera::targetPlanePoint(const QPointF& pixel, const QSize& size) const {
    const Ray cursor = ray(pixel, size);
    if (orthographic_)
        return cursor.at(farPlane() + distance_);
    const float cosine = QVector3D::dotProduct(cursor.direction, forward());
    return cursor.at(distance_ / std::max(cosine, 1e-3f));
}

QPointF OrbitCamera::project(const QVector3D& point, const QSize& size) const {
    const QVector3D ndc = (projectionMatrix(aspectOf(size)) * viewMatrix()).map(point);
    return {(ndc.x() + 1.0) * 0.5 * size.width(), (1.0 - ndc.y()) * 0.5 * size.height()};
}

float OrbitCamera::metresPerPixel(float depth, const QSize& size) const {
    const float halfHeight =
        orthographic_ ? orthographicHalfHeight() : depth * tanHalfFieldOfView();
    return 2.0f * halfHeight / float(std::max(size.height(), 1));
}

void OrbitCamera::fit(const Aabb& box, float aspectRatio) {
    const Vec3d centre = box.center();
    target_ = QVector3D(float(centre.x()), float(centre.y()), float(centre.z()));
    sceneRadius_ = std::max(float(0.5 * box.size().norm()), 1e-3f);
    // For each corner, in the eye's frame around the target, the distance at which it just
    // touches the frustum's side planes; the largest of these frames the whole box snugly.
    const float tanVertical = tanHalfFieldOfView();
    const float tanHorizontal = tanVertical * std::max(aspectRatio, 1e-3f);
    const QVector3D sideways = right();
    const QVector3D upwards = up();
    const QVector3D ahead = forward();
    float needed = 0.0f;
    for (int i = 0; i < 8; ++i) {
        const Vec3d corner((i & 1 ? box.max : box.min).x(), (i & 2 ? box.max : box.min).y(),
                           (i & 4 ? box.max : box.min).z());
        const QVector3D offset =
            QVector3D(float(corner.x()), float(corner.y()), float(corner.z())) - target_;
        // Orthographic: the view's half-height at the target is what must hold the corner.
        const float depth = orthographic_ ? 0.0f : QVector3D::dotProduct(offset, ahead);
        needed = std::max(
            {needed, std::abs(QVector3D::dotProduct(offset, sideways)) / tanHorizontal - depth,
             std::abs(QVector3D::dotProduct(offset, upwards)) / tanVertical - depth});
    }
    setDistance(needed * kFitMargin);
}

void OrbitCamera::orbit(float yawDegrees, float pitchDegrees) {
    setAngles(yaw_ + yawDegrees, pitch_ + pitchDegrees);
}

void OrbitCamera::pan(const QPointF& pixelDelta, const QSize& size) {
    const float metres = metresPerPixel(distance_, size);
    // Dragging right moves the scene right, which moves the camera left.
    target_ += (-right() * float(pixelDelta.x()) + up() * float(pixelDelta.y())) * metres;
}

void OrbitCamera::zoom(float factor) {
    setDistance(distance_ * factor);
}

void OrbitCamera::zoomToward(const QPointF& pixel, const QSize& size, float factor) {
    const QVector3D anchor = targetPlanePoint(pixel, size);
    const float before = distance_;
    zoom(factor);
    // Scaling the whole eye-target-anchor picture about the eye's line keeps the anchor's pixel.
    const float applied = distance_ / before;
    target_ = anchor + (target_ - anchor) * applied;
}

} // namespace airtrap
