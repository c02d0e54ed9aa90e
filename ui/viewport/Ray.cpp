#include "viewport/Ray.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace airtrap {

std::optional<float> Ray::hitBox(const QVector3D& min, const QVector3D& max) const {
    // Slab method: intersect the ray's parameter interval with each axis' slab in turn.
    float enter = 0.0f;
    float exit = std::numeric_limits<float>::max();
    for (int axis = 0; axis < 3; ++axis) {
        const float o = origin[axis];
        const float d = direction[axis];
        if (std::abs(d) < 1e-12f) {
            if (o < min[axis] || o > max[axis]) {
                return std::nullopt;
            }
            continue;
        }
        float near = (min[axis] - o) / d;
        float far = (max[axis] - o) / d;
        if (near > far) {
            std::swap(near, far);
        }
        enter = std::max(enter, near);
        exit = std::min(exit, far);
        if (enter > exit) {
            return std::nullopt;
        }
    }
    return enter;
}

Ray::SegmentApproach Ray::approach(const QVector3D& a, const QVector3D& b) const {
    // Closest points of two lines, each parameter then clamped to its half-line or segment.
    const QVector3D edge = b - a;
    const QVector3D offset = origin - a;
    const float edgeLengthSquared = QVector3D::dotProduct(edge, edge);
    const float cosine = QVector3D::dotProduct(direction, edge);
    const float rayOffset = QVector3D::dotProduct(direction, offset);
    const float edgeOffset = QVector3D::dotProduct(edge, offset);
    const float denominator = edgeLengthSquared - cosine * cosine;

    float alongEdge = 0.0f; // as a fraction of the segment
    if (edgeLengthSquared > 0.0f && denominator > 1e-12f * edgeLengthSquared) {
        alongEdge = (edgeOffset - cosine * rayOffset) / denominator;
    }
    alongEdge = std::clamp(alongEdge, 0.0f, 1.0f);
    const QVector3D onEdge = a + edge * alongEdge;
    const float alongRay = std::max(0.0f, QVector3D::dotProduct(onEdge - origin, direction));
    // Re-project onto the segment from the clamped ray point: exact when either clamp was active.
    if (edgeLengthSquared > 0.0f) {
        alongEdge = std::clamp(QVector3D::dotProduct(at(alongRay) - a, edge) / edgeLengthSquared,
                               0.0f, 1.0f);
    }
    return {alongRay, (at(alongRay) - (a + edge * alongEdge)).length()};
}

} // namespace airtrap
