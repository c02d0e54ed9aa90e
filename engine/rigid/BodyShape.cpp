#include "rigid/BodyShape.h"

#include "core/Error.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace airtrap {
namespace {

//! Unit vector along `axis` with the sign of `value` (+ for 0).
Vec3d signedAxis(int axis, double value) {
    Vec3d n = Vec3d::Zero();
    n[axis] = value < 0.0 ? -1.0 : 1.0;
    return n;
}

} // namespace

BodyShape::BodyShape(Kind kind, const Vec3d& size, double boundingRadius)
    : kind_(kind), size_(size), boundingRadius_(boundingRadius) {}

BodyShape BodyShape::box(const Vec3d& size) {
    return BodyShape(Kind::Box, 0.5 * size, 0.5 * size.norm());
}

BodyShape BodyShape::sphere(double radius) {
    return BodyShape(Kind::Sphere, Vec3d::Constant(radius), radius);
}

BodyShape BodyShape::cylinder(double radius, double height) {
    return BodyShape(Kind::Cylinder, Vec3d(radius, 0.5 * height, radius),
                     std::hypot(radius, 0.5 * height));
}

BodyShape BodyShape::mesh(std::shared_ptr<const SignedDistanceField> field) {
    if (!field)
        throw Error(ErrorKind::InvalidInput, "a mesh shape needs a signed distance field");
    const Aabb bounds = field->bounds();
    const double radius = bounds.min.cwiseAbs().cwiseMax(bounds.max.cwiseAbs()).norm();
    BodyShape shape(Kind::Mesh, bounds.size(), radius);
    shape.field_ = std::move(field);
    return shape;
}

BodyShape BodyShape::tank(const Aabb& inside) {
    BodyShape shape(Kind::Tank, inside.size(), std::numeric_limits<double>::infinity());
    shape.tankInside_ = inside;
    return shape;
}

double BodyShape::signedDistance(const Vec3d& x) const {
    switch (kind_) {
    case Kind::Box:
        return boxDistance(x);
    case Kind::Sphere:
        return x.norm() - size_.x();
    case Kind::Cylinder:
        return cylinderDistance(x);
    case Kind::Mesh:
        return field_->distance(x);
    case Kind::Tank:
        return tankDistance(x);
    }
    return 0.0;
}

double BodyShape::clearanceBound(const Vec3d& x) const {
    switch (kind_) {
    case Kind::Mesh:
        return -std::numeric_limits<double>::infinity();
    case Kind::Tank:
        return tankWallsDistance(x);
    default: // exact distances
        return signedDistance(x);
    }
}

Vec3d BodyShape::normal(const Vec3d& x) const {
    switch (kind_) {
    case Kind::Box:
        return boxNormal(x);
    case Kind::Sphere: {
        const double length = x.norm();
        return length > 0.0 ? Vec3d(x / length) : Vec3d::UnitY();
    }
    case Kind::Cylinder:
        return cylinderNormal(x);
    case Kind::Mesh:
        return field_->normal(x);
    case Kind::Tank:
        return tankNormal(x);
    }
    return Vec3d::UnitY();
}

double BodyShape::boxDistance(const Vec3d& x) const {
    const Vec3d q = x.cwiseAbs() - size_;
    return q.cwiseMax(0.0).norm() + std::min(q.maxCoeff(), 0.0);
}

Vec3d BodyShape::boxNormal(const Vec3d& x) const {
    const Vec3d q = x.cwiseAbs() - size_;
    if (q.maxCoeff() > 0.0) {
        // Outside: from the nearest point of the box, which clamps each coordinate.
        const Vec3d outward = q.cwiseMax(0.0).cwiseProduct(x.cwiseSign());
        return outward.normalized();
    }
    int axis = 0;
    q.maxCoeff(&axis);
    return signedAxis(axis, x[axis]);
}

double BodyShape::cylinderDistance(const Vec3d& x) const {
    const double radial = std::hypot(x.x(), x.z()) - size_.x();
    const double axial = std::abs(x.y()) - size_.y();
    return std::hypot(std::max(radial, 0.0), std::max(axial, 0.0)) +
           std::min(std::max(radial, axial), 0.0);
}

Vec3d BodyShape::cylinderNormal(const Vec3d& x) const {
    const double planar = std::hypot(x.x(), x.z());
    const Vec3d radialDirection =
        planar > 0.0 ? Vec3d(x.x() / planar, 0.0, x.z() / planar) : Vec3d::UnitX();
    const Vec3d axialDirection = signedAxis(1, x.y());
    const double radial = planar - size_.x();
    const double axial = std::abs(x.y()) - size_.y();
    if (radial > 0.0 && axial > 0.0)
        return (radial * radialDirection + axial * axialDirection).normalized();
    return radial > axial ? radialDirection : axialDirection;
}

double BodyShape::tankDistance(const Vec3d& x) const {
    // Positive inside the tank, where the water is; the solid is everything else below the rim.
    double clearance = x.y() - tankInside_.min.y();
    if (x.y() <= tankInside_.max.y())
        for (int axis : {0, 2})
            clearance = std::min(
                {clearance, x[axis] - tankInside_.min[axis], tankInside_.max[axis] - x[axis]});
    return clearance;
}

double BodyShape::tankWallsDistance(const Vec3d& x) const {
    // The nearest of the floor and the four wall planes: equal to tankDistance() below the rim,
    // never above it, and a true distance, since the minimum of plane distances is one.
    double clearance = x.y() - tankInside_.min.y();
    for (int axis : {0, 2})
        clearance =
            std::min({clearance, x[axis] - tankInside_.min[axis], tankInside_.max[axis] - x[axis]});
    return clearance;
}

Vec3d BodyShape::tankNormal(const Vec3d& x) const {
    Vec3d best = Vec3d::UnitY();
    double clearance = x.y() - tankInside_.min.y();
    if (x.y() > tankInside_.max.y())
        return best;
    for (int axis : {0, 2}) {
        const double toMin = x[axis] - tankInside_.min[axis];
        const double toMax = tankInside_.max[axis] - x[axis];
        if (toMin < clearance) {
            clearance = toMin;
            best = signedAxis(axis, 1.0);
        }
        if (toMax < clearance) {
            clearance = toMax;
            best = signedAxis(axis, -1.0);
        }
    }
    return best;
}

} // namespace airtrap
