#pragma once
// Meshes as Wavefront OBJ, one file per frame (`water_0001.obj`, `bubbles_0001.obj`,
// `bodies_0001.obj`; docs/CLI.md "export"): one `o` object per named mesh, `v` positions in metres,
// `vn` area-weighted vertex normals, triangles as `f v//vn`. Text, because every renderer reads it
// and an artist can open it; one object per bubble or body, so they can be picked apart.
#include "core/UpAxis.h"
#include "post/NamedMesh.h"

#include <string>
#include <vector>

namespace airtrap {

class ObjExporter {
public:
    //! The whole file. `comments` become `#` lines at the top. An empty list gives a file with
    //! no objects, which keeps a sequence whole when a frame has nothing to show.
    static std::string encode(const std::vector<NamedMesh>& objects, UpAxis up,
                              const std::vector<std::string>& comments = {});
    //! Writes the file atomically; Error(Io) names `path` and the reason.
    static void write(const std::string& path, const std::vector<NamedMesh>& objects, UpAxis up,
                      const std::vector<std::string>& comments = {});
};

} // namespace airtrap
