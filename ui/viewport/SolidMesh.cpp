#include "viewport/SolidMesh.h"

#include "viewport/QtVectors.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace airtrap {

namespace {

// Fine enough that a sphere's outline looks round at the sizes bodies are drawn at.
constexpr int kSegments = 32;
constexpr int kRings = 16;

QVector3D onSphere(int ring, int segment) {
    const float polar = std::numbers::pi_v<float> * float(ring) / float(kRings);
    const float azimuth = 2.0f * std::numbers::pi_v<float> * float(segment) / float(kSegments);
    return QVector3D(std::sin(polar) * std::cos(azimuth), std::cos(polar),
                     std::sin(polar) * std::sin(azimuth));
}

QVector3D around(int segment) {
    const float azimuth = 2.0f * std::numbers::pi_v<float> * float(segment) / float(kSegments);
    return QVector3D(std::cos(azimuth), 0.0f, std::sin(azimuth));
}

//! Möller–Trumbore: distance along the ray to triangle (a, b, c), or a negative number.
float rayTriangle(const Ray& ray, const QVector3D& a, const QVector3D& b, const QVector3D& c) {
    const QVector3D ab = b - a;
    const QVector3D ac = c - a;
    const QVector3D p = QVector3D::crossProduct(ray.direction, ac);
    const float determinant = QVector3D::dotProduct(ab, p);
    if (std::abs(determinant) < 1e-12f)
        return -1.0f;
    const QVector3D offset = ray.origin - a;
    const float u = QVector3D::dotProduct(offset, p) / determinant;
    if (u < 0.0f || u > 1.0f)
        return -1.0f;
    const QVector3D q = QVector3D::crossProduct(offset, ab);
    const float v = QVector3D::dotProduct(ray.direction, q) / determinant;
    if (v < 0.0f || u + v > 1.0f)
        return -1.0f;
    return QVector3D::dotProduct(ac, q) / determinant;
}

} // namespace

void SolidMesh::addTriangle(const Vertex& a, const Vertex& b, const Vertex& c) {
    vertices.insert(vertices.end(), {a, b, c});
}

void SolidMesh::addFlatTriangle(const QVector3D& a, const QVector3D& b, const QVector3D& c) {
    const QVector3D normal = QVector3D::crossProduct(b - a, c - a).normalized();
    addTriangle({a, normal}, {b, normal}, {c, normal});
}

SolidMesh SolidMesh::box(const QVector3D& size) {
    SolidMesh solid;
    const QVector3D half = 0.5f * size;
    // Each face: its outward axis, and two axes spanning it in counter-clockwise order.
    for (int axis = 0; axis < 3; ++axis) {
        for (const float sign : {-1.0f, 1.0f}) {
            QVector3D normal, u, v;
            normal[axis] = sign;
            u[(axis + 1) % 3] = 1.0f;
            v[(axis + 2) % 3] = sign;
            const QVector3D centre = normal * half[axis];
            const QVector3D du = u * half[(axis + 1) % 3];
            const QVector3D dv = v * half[(axis + 2) % 3];
            const QVector3D corners[4] = {centre - du - dv, centre + du - dv, centre + du + dv,
                                          centre - du + dv};
            solid.addTriangle({corners[0], normal}, {corners[1], normal}, {corners[2], normal});
            solid.addTriangle({corners[0], normal}, {corners[2], normal}, {corners[3], normal});
        }
    }
    return solid;
}

SolidMesh SolidMesh::sphere(float radius) {
    SolidMesh solid;
    for (int ring = 0; ring < kRings; ++ring) {
        for (int segment = 0; segment < kSegments; ++segment) {
            const QVector3D n[4] = {onSphere(ring, segment), onSphere(ring, segment + 1),
                                    onSphere(ring + 1, segment + 1), onSphere(ring + 1, segment)};
            const auto vertex = [&](int i) { return Vertex{n[i] * radius, n[i]}; };
            solid.addTriangle(vertex(0), vertex(1), vertex(2));
            solid.addTriangle(vertex(0), vertex(2), vertex(3));
        }
    }
    return solid;
}

SolidMesh SolidMesh::cylinder(float radius, float height) {
    SolidMesh solid;
    const QVector3D top(0.0f, 0.5f * height, 0.0f);
    const QVector3D up(0.0f, 1.0f, 0.0f);
    for (int segment = 0; segment < kSegments; ++segment) {
        const QVector3D a = around(segment);
        const QVector3D b = around(segment + 1);
        const Vertex wall[4] = {{a * radius - top, a},
                                {b * radius - top, b},
                                {b * radius + top, b},
                                {a * radius + top, a}};
        solid.addTriangle(wall[0], wall[2], wall[1]);
        solid.addTriangle(wall[0], wall[3], wall[2]);
        solid.addTriangle({top, up}, {b * radius + top, up}, {a * radius + top, up});
        solid.addTriangle({-top, -up}, {a * radius - top, -up}, {b * radius - top, -up});
    }
    return solid;
}

SolidMesh SolidMesh::fromMesh(const TriangleMesh& mesh) {
    SolidMesh solid;
    solid.vertices.reserve(3 * mesh.triangleCount());
    for (const TriangleMesh::Triangle& triangle : mesh.triangles)
        solid.addFlatTriangle(toQVector3D(mesh.vertices[triangle[0]]),
                              toQVector3D(mesh.vertices[triangle[1]]),
                              toQVector3D(mesh.vertices[triangle[2]]));
    return solid;
}

float SolidMesh::boundingRadius() const {
    float radius = 0.0f;
    for (const Vertex& vertex : vertices)
        radius = std::max(radius, vertex.position.length());
    return radius;
}

std::optional<float> SolidMesh::hit(const Ray& ray) const {
    float nearest = -1.0f;
    for (std::size_t i = 0; i + 2 < vertices.size(); i += 3) {
        const float distance = rayTriangle(ray, vertices[i].position, vertices[i + 1].position,
                                           vertices[i + 2].position);
        if (distance >= 0.0f && (nearest < 0.0f || distance < nearest))
            nearest = distance;
    }
    if (nearest < 0.0f)
        return std::nullopt;
    return nearest;
}

} // namespace airtrap
