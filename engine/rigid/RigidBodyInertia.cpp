#include "rigid/RigidBodyInertia.h"

#include "core/Error.h"

#include <Eigen/Cholesky>
#include <cmath>
#include <limits>
#include <string>

namespace airtrap {
namespace {

[[noreturn]] void invalidInertia(const std::string& what) {
    throw Error(ErrorKind::InvalidInput, "rigid body inertia: " + what);
}

void checkTensor(const Mat3d& inertia) {
    if (!inertia.allFinite())
        invalidInertia("the inertia tensor is not finite");
    // Relative tolerance: tensors integrated from a mesh are symmetric only up to rounding.
    const double scale = inertia.cwiseAbs().maxCoeff();
    if ((inertia - inertia.transpose()).cwiseAbs().maxCoeff() > 1e-9 * scale)
        invalidInertia("the inertia tensor is not symmetric");
    if (inertia.llt().info() != Eigen::Success)
        invalidInertia("the inertia tensor is not positive definite");
}

} // namespace

RigidBodyInertia::RigidBodyInertia(double mass, const Mat3d& inertiaBody) {
    if (!std::isfinite(mass) || mass <= 0.0)
        invalidInertia("mass must be finite and > 0 kg, got " + std::to_string(mass));
    checkTensor(inertiaBody);
    mass_ = mass;
    inverseMass_ = 1.0 / mass;
    // Symmetrise so that R I⁻¹ Rᵀ stays exactly symmetric in every later product.
    inertiaBody_ = 0.5 * (inertiaBody + inertiaBody.transpose());
    const Mat3d inverse = inertiaBody_.inverse();
    inverseInertiaBody_ = 0.5 * (inverse + inverse.transpose());
}

RigidBodyInertia RigidBodyInertia::infinite() {
    RigidBodyInertia inertia;
    const double inf = std::numeric_limits<double>::infinity();
    inertia.mass_ = inf;
    inertia.inverseMass_ = 0.0;
    inertia.inertiaBody_ = Vec3d::Constant(inf).asDiagonal();
    inertia.inverseInertiaBody_ = Mat3d::Zero();
    return inertia;
}

Mat3d RigidBodyInertia::inverseInertiaWorld(const Quatd& orientation) const {
    const Mat3d r = orientation.toRotationMatrix();
    return r * inverseInertiaBody_ * r.transpose();
}

Mat3d RigidBodyInertia::inertiaWorld(const Quatd& orientation) const {
    const Mat3d r = orientation.toRotationMatrix();
    return r * inertiaBody_ * r.transpose();
}

} // namespace airtrap
