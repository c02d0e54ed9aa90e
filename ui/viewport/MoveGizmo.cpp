#include "viewport/MoveGizmo.h"

#include <QLineF>
#include <cmath>

namespace airtrap {

namespace {

const QColor kAxisColours[3] = {QColor(235, 75, 75), QColor(110, 215, 90), QColor(80, 130, 255)};
const QColor kDraggedColour(255, 220, 60);
//! The arrows' length as a share of the view's height, whatever the zoom.
constexpr float kArmShareOfView = 0.12f;
//! How near (pixels) the cursor must come to an arrow to take it.
constexpr double kGrabPixels = 8.0;
//! The arrows start this share of the arm away from the centre, which stays visible (and a click
//! there picks what is under it).
constexpr float kGapShare = 0.3f;
//! Arrowheads: length and half-width as a share of the arm.
constexpr float kHeadLength = 0.2f;
constexpr float kHeadHalfWidth = 0.07f;
//! Offsets are rounded to this, m: scene files then hold round numbers.
constexpr double kOffsetStep = 0.001;
//! Below this sine between the axis and the view, motion along the axis cannot be read.
constexpr double kMinimumSine = 0.05;

QVector3D unit(int axis) {
    QVector3D direction;
    direction[axis] = 1.0f;
    return direction;
}

double distanceToSegment(const QPointF& p, const QPointF& a, const QPointF& b) {
    const QPointF ab = b - a;
    const double lengthSquared = QPointF::dotProduct(ab, ab);
    const double t = lengthSquared > 0.0
                         ? std::clamp(QPointF::dotProduct(p - a, ab) / lengthSquared, 0.0, 1.0)
                         : 0.0;
    return QLineF(p, a + t * ab).length();
}

} // namespace

MoveGizmo::MoveGizmo() {
    lines_.setWidth(3.0f);
    // Over everything: an arrow inside a body or under the water must still be grabbed.
    lines_.setDepthTested(false);
}

void MoveGizmo::setOrigin(std::optional<QVector3D> origin) {
    origin_ = origin;
    rebuild();
}

void MoveGizmo::fitTo(const OrbitCamera& camera, const QSize& size) {
    if (!origin_)
        return;
    const float depth = QVector3D::dotProduct(*origin_ - camera.eye(), camera.forward());
    armLength_ = kArmShareOfView * float(size.height()) *
                 camera.metresPerPixel(std::max(depth, 1e-3f), size);
    rebuild();
}

std::optional<int> MoveGizmo::axisAt(const QPointF& pixel, const OrbitCamera& camera,
                                     const QSize& size) const {
    if (!origin_)
        return std::nullopt;
    std::optional<int> nearest;
    double nearestDistance = kGrabPixels;
    for (int axis = 0; axis < 3; ++axis) {
        const QPointF start =
            camera.project(*origin_ + unit(axis) * (kGapShare * armLength_), size);
        const QPointF tip = camera.project(*origin_ + unit(axis) * armLength_, size);
        const double distance = distanceToSegment(pixel, start, tip);
        if (distance <= nearestDistance) {
            nearestDistance = distance;
            nearest = axis;
        }
    }
    return nearest;
}

bool MoveGizmo::beginDrag(int axis, const QPointF& pixel, const OrbitCamera& camera,
                          const QSize& size) {
    const std::optional<double> start = axisParameter(axis, pixel, camera, size);
    if (!start)
        return false;
    dragAxis_ = axis;
    dragStart_ = *start;
    rebuild();
    return true;
}

double MoveGizmo::dragOffset(const QPointF& pixel, const OrbitCamera& camera,
                             const QSize& size) const {
    if (!dragAxis_)
        return 0.0;
    const std::optional<double> now = axisParameter(*dragAxis_, pixel, camera, size);
    if (!now)
        return 0.0;
    return std::round((*now - dragStart_) / kOffsetStep) * kOffsetStep;
}

void MoveGizmo::endDrag() {
    dragAxis_.reset();
    rebuild();
}

std::optional<double> MoveGizmo::axisParameter(int axis, const QPointF& pixel,
                                               const OrbitCamera& camera, const QSize& size) const {
    if (!origin_)
        return std::nullopt;
    // Nearest points of the axis line origin + s·a and the cursor ray o + t·d (unit vectors).
    const Ray ray = camera.ray(pixel, size);
    const QVector3D a = unit(axis);
    const QVector3D w = *origin_ - ray.origin;
    const double b = QVector3D::dotProduct(a, ray.direction);
    const double sineSquared = 1.0 - b * b;
    if (sineSquared < kMinimumSine * kMinimumSine)
        return std::nullopt;
    const double along = QVector3D::dotProduct(a, w);
    const double across = QVector3D::dotProduct(ray.direction, w);
    return (b * across - along) / sineSquared;
}

void MoveGizmo::rebuild() {
    std::vector<LineVertex> vertices;
    if (origin_) {
        const auto segment = [&vertices](const QVector3D& from, const QVector3D& to,
                                         const QColor& colour) {
            vertices.push_back(LineVertex::at(from, colour));
            vertices.push_back(LineVertex::at(to, colour));
        };
        for (int axis = 0; axis < 3; ++axis) {
            const QColor colour = dragAxis_ == axis ? kDraggedColour : kAxisColours[axis];
            const QVector3D tip = *origin_ + unit(axis) * armLength_;
            segment(*origin_ + unit(axis) * (kGapShare * armLength_), tip, colour);
            // A head in each of the two planes through the axis, so it reads from any side.
            const QVector3D back = unit(axis) * (kHeadLength * armLength_);
            for (int side : {(axis + 1) % 3, (axis + 2) % 3}) {
                const QVector3D spread = unit(side) * (kHeadHalfWidth * armLength_);
                segment(tip, tip - back + spread, colour);
                segment(tip, tip - back - spread, colour);
            }
        }
    }
    lines_.setSegments(std::move(vertices));
}

void MoveGizmo::initialize() {
    lines_.initialize();
}

void MoveGizmo::draw(const RenderContext& context) {
    if (origin_)
        lines_.draw(context);
}

void MoveGizmo::release() {
    lines_.release();
}

} // namespace airtrap
