#pragma once
// A half-line in world space, for picking: from the camera's eye through a pixel.
#include <QVector3D>
#include <optional>

namespace airtrap {

struct Ray {
    QVector3D origin;
    QVector3D direction; //!< unit length

    //! The point `distance` metres along the ray.
    QVector3D at(float distance) const { return origin + direction * distance; }

    //! Distance along the ray to where it enters the axis-aligned box [min, max]; 0 when the
    //! origin is inside it; nothing when the ray misses it or the box is behind the origin.
    std::optional<float> hitBox(const QVector3D& min, const QVector3D& max) const;

    //! Where the ray passes closest to the segment [a, b].
    struct SegmentApproach {
        float alongRay = 0.0f; //!< distance along the ray to its closest point
        float gap = 0.0f;      //!< distance between the two closest points
    };
    //! The closest approach of the ray (distances ≥ 0 only) to the segment [a, b].
    SegmentApproach approach(const QVector3D& a, const QVector3D& b) const;
};

} // namespace airtrap
