#include "post/OscillatingBubbleMesh.h"

#include "post/Icosphere.h"

#include <cmath>

namespace airtrap {

OscillatingBubbleMesh::OscillatingBubbleMesh(const BubbleMeshSettings& settings)
    : settings_(settings), unitSphere_(unitIcosphere(settings.subdivisions)) {
    // A tessellated sphere encloses less than the sphere (3.4 % less at 2 subdivisions): grown
    // to the sphere's volume, the mesh carries exactly the air the simulation had.
    const double grow = std::cbrt(4.0 / 3.0 * kPi / unitSphere_.signedVolume());
    for (Vec3d& vertex : unitSphere_.vertices)
        vertex *= grow;
}

double OscillatingBubbleMesh::deformation(double radius, double age) const {
    const double period = settings_.duration;
    if (!(age > 0.0 && age <= period))
        return 0.0;
    const double phase = age / period;
    return settings_.magnitude * radius * (phase - 1.0) * (phase - 1.0) *
           std::sin(2.0 * kPi * settings_.cycles * phase);
}

Vec3d OscillatingBubbleMesh::semiAxes(double radius, double age) const {
    const double across = radius + deformation(radius, age);
    return {across, across, radius * radius * radius / (across * across)};
}

Quatd OscillatingBubbleMesh::alignment(const Vec3d& velocity) {
    if (!(velocity.squaredNorm() > 0.0) || !velocity.allFinite())
        return Quatd::Identity();
    return Quatd::FromTwoVectors(Vec3d::UnitZ(), velocity);
}

TriangleMesh OscillatingBubbleMesh::build(const BubbleState& bubble) const {
    const Vec3d axes = semiAxes(bubble.radius, bubble.age);
    const Quatd turn = alignment(bubble.body.linearVelocity);
    TriangleMesh mesh;
    mesh.triangles = unitSphere_.triangles;
    mesh.vertices.reserve(unitSphere_.vertices.size());
    for (const Vec3d& p : unitSphere_.vertices)
        mesh.vertices.push_back(bubble.body.position + turn * axes.cwiseProduct(p));
    return mesh;
}

} // namespace airtrap
