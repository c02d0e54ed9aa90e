#pragma once
// A body's surface as the viewport draws and picks it: triangles in the body's shape frame, three
// vertices each, with normals (smooth on spheres and cylinder walls, flat elsewhere). The
// primitives are tessellated here; a mesh body's triangles come from the engine's loader.
#include "rigid/TriangleMesh.h"
#include "viewport/Ray.h"

#include <QVector3D>
#include <optional>
#include <vector>

namespace airtrap {

struct SolidMesh {
    struct Vertex {
        QVector3D position; //!< m, shape frame
        QVector3D normal;   //!< unit, outward
    };
    std::vector<Vertex> vertices; //!< three per triangle

    //! Box of edge lengths `size`, centred at the origin.
    static SolidMesh box(const QVector3D& size);
    //! Sphere of `radius` centred at the origin.
    static SolidMesh sphere(float radius);
    //! Capped cylinder of `radius` and `height` along y, centred at the origin.
    static SolidMesh cylinder(float radius, float height);
    //! The triangles of `mesh`, with flat normals.
    static SolidMesh fromMesh(const TriangleMesh& mesh);

    int vertexCount() const { return int(vertices.size()); }
    //! Distance from the origin to the farthest vertex, m.
    float boundingRadius() const;
    //! Distance along `ray` (in the shape frame) to the nearest triangle it crosses, from either
    //! side; nothing when it misses them all.
    std::optional<float> hit(const Ray& ray) const;

private:
    void addTriangle(const Vertex& a, const Vertex& b, const Vertex& c);
    void addFlatTriangle(const QVector3D& a, const QVector3D& b, const QVector3D& c);
};

} // namespace airtrap
