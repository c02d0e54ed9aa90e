#pragma once
#include "rigid/TriangleMesh.h"

#include <string>

namespace airtrap {

//! A mesh with the name it is exported under (an OBJ object, a body's scene name).
struct NamedMesh {
    std::string name;
    TriangleMesh mesh;
};

} // namespace airtrap
