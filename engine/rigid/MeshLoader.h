#pragma once
// Reads a rigid body's shape from a mesh file and refuses, with the path and the reason, any mesh
// that does not bound a solid (docs/SCENE_FORMAT.md "Validation"): mass properties, the signed
// distance field and inside tests all assume a closed, consistently oriented surface.
#include "rigid/TriangleMesh.h"

#include <string>

namespace airtrap {

class MeshLoader {
public:
    //! Loads every triangle of the file at `path` (any format assimp reads: OBJ, PLY, STL, …),
    //! with node transforms applied, polygons triangulated and vertices at the same position
    //! joined (so an STL triangle soup becomes indexed), then multiplies positions by `scale`
    //! (file units → m). An inside-out closed mesh is turned outward without comment.
    //! Positions pass through assimp's single precision: about seven significant digits.
    //! @throw Error (InvalidInput), naming `path`: unreadable file, no triangles, a surface that
    //! is not closed, not manifold, inconsistently oriented or of no volume, a bad `scale`.
    static TriangleMesh load(const std::string& path, double scale = 1.0);

    //! The checks `load` makes on a welded mesh, for meshes built in code; `source` names it
    //! in the message. Flips an inside-out mesh.
    static void checkSolid(TriangleMesh& mesh, const std::string& source);

private:
    static TriangleMesh readTriangles(const std::string& path);
    //! Joins vertices with identical coordinates and drops triangles that collapse.
    static TriangleMesh weldByPosition(const TriangleMesh& soup);
};

} // namespace airtrap
