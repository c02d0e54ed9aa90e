#pragma once
// The solid a rigid body occupies, in its shape frame (box, sphere and cylinder centred at the
// origin, a mesh in its file's coordinates, the tank as the open-top box the water lives in):
// signed distance and outward normal for rigid–rigid contacts (docs/METHOD.md "Contacts between
// bodies") and the t = 0 overlap check. Mesh shapes answer from their OpenVDB signed distance
// field.
#include "core/Math.h"
#include "rigid/SignedDistanceField.h"

#include <memory>

namespace airtrap {

class BodyShape {
public:
    enum class Kind { Box, Sphere, Cylinder, Mesh, Tank };

    static BodyShape box(const Vec3d& size);
    static BodyShape sphere(double radius);
    //! Along the local y axis, centred at the origin.
    static BodyShape cylinder(double radius, double height);
    static BodyShape mesh(std::shared_ptr<const SignedDistanceField> field);
    //! The walls and floor around the open-top box `inside`: solid everywhere outside it below
    //! the rim (walls as thick as needed), nothing above the rim.
    static BodyShape tank(const Aabb& inside);

    Kind kind() const { return kind_; }
    //! Distance to the surface at shape-frame `x`, m: negative inside the solid.
    double signedDistance(const Vec3d& x) const;
    //! A lower bound of signedDistance() that changes by no more than the distance moved, so
    //! every point within r of `x` lies at least clearanceBound(x) − r outside the solid: one
    //! query clears a whole body of contacts. A tank's ignores the rim (walls taken as endless);
    //! a mesh's field is only sampled, so it claims no bound (−∞).
    double clearanceBound(const Vec3d& x) const;
    //! Outward unit normal of the solid's surface nearest to `x` (the direction in which the
    //! signed distance grows fastest).
    Vec3d normal(const Vec3d& x) const;
    //! Radius of a sphere about the shape origin that holds the whole solid; infinite for a
    //! tank.
    double boundingRadius() const { return boundingRadius_; }
    //! The sphere's radius; only for Kind::Sphere.
    double radius() const { return size_.x(); }

private:
    BodyShape(Kind kind, const Vec3d& size, double boundingRadius);

    double boxDistance(const Vec3d& x) const;
    Vec3d boxNormal(const Vec3d& x) const;
    double cylinderDistance(const Vec3d& x) const;
    Vec3d cylinderNormal(const Vec3d& x) const;
    double tankDistance(const Vec3d& x) const;
    double tankWallsDistance(const Vec3d& x) const;
    Vec3d tankNormal(const Vec3d& x) const;

    Kind kind_;
    Vec3d size_; //!< box: half extents; sphere: (r, r, r); cylinder: (r, h/2, r)
    double boundingRadius_;
    Aabb tankInside_;
    std::shared_ptr<const SignedDistanceField> field_;
};

} // namespace airtrap
