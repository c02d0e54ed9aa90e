#include "rigid/MeshLoader.h"

#include "core/Error.h"
#include "rigid/ObjText.h"

#include <assimp/Importer.hpp>
#include <assimp/postprocess.h>
#include <assimp/scene.h>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <unordered_map>

namespace airtrap {

namespace {

[[noreturn]] void refuse(const std::string& source, const std::string& what) {
    throw Error(ErrorKind::InvalidInput, source + ": " + what);
}

//! Exact coordinates as a hash key; −0 and +0 are one position.
struct PositionKey {
    double x, y, z;
    bool operator==(const PositionKey&) const = default;
};

struct PositionHash {
    std::size_t operator()(const PositionKey& key) const {
        const std::hash<double> hash;
        std::size_t seed = hash(key.x + 0.0);
        // Boost's hash_combine constant: spreads the bits of each coordinate over the seed.
        for (double coordinate : {key.y, key.z})
            seed ^= hash(coordinate + 0.0) + 0x9e3779b97f4a7c15ULL + (seed << 6) + (seed >> 2);
        return seed;
    }
};

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        refuse(path, "cannot open the file");
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

Eigen::Affine3d toEigen(const aiMatrix4x4& m) {
    Eigen::Matrix4d matrix;
    matrix << m.a1, m.a2, m.a3, m.a4, m.b1, m.b2, m.b3, m.b4, m.c1, m.c2, m.c3, m.c4, m.d1, m.d2,
        m.d3, m.d4;
    return Eigen::Affine3d(matrix);
}

void appendTriangles(const aiMesh& mesh, const Eigen::Affine3d& toScene, TriangleMesh& out) {
    const auto first = static_cast<std::uint32_t>(out.vertices.size());
    const std::size_t firstTriangle = out.triangles.size();
    for (unsigned v = 0; v < mesh.mNumVertices; ++v) {
        const aiVector3D& p = mesh.mVertices[v];
        out.vertices.push_back(toScene * Vec3d(p.x, p.y, p.z));
    }
    for (unsigned f = 0; f < mesh.mNumFaces; ++f) {
        const aiFace& face = mesh.mFaces[f];
        if (face.mNumIndices != 3)
            continue; // points and lines bound nothing
        out.triangles.push_back(
            {first + face.mIndices[0], first + face.mIndices[1], first + face.mIndices[2]});
    }
    if (toScene.linear().determinant() < 0.0) // a mirroring node turns its meshes inside-out
        for (std::size_t t = firstTriangle; t < out.triangles.size(); ++t)
            std::swap(out.triangles[t][1], out.triangles[t][2]);
}

//! Every mesh the node tree places, with its nodes' transforms applied (formats with a scene
//! graph, such as glTF, FBX or Collada, place and instance meshes there; OBJ, PLY, STL do not).
void appendNode(const aiScene& scene, const aiNode& node, const Eigen::Affine3d& parentToScene,
                TriangleMesh& out) {
    const Eigen::Affine3d toScene = parentToScene * toEigen(node.mTransformation);
    for (unsigned m = 0; m < node.mNumMeshes; ++m)
        appendTriangles(*scene.mMeshes[node.mMeshes[m]], toScene, out);
    for (unsigned c = 0; c < node.mNumChildren; ++c)
        appendNode(scene, *node.mChildren[c], toScene, out);
}

} // namespace

TriangleMesh MeshLoader::load(const std::string& path, double scale) {
    if (!std::isfinite(scale) || scale <= 0.0)
        refuse(path, "scale must be a positive number, got " + std::to_string(scale));
    TriangleMesh mesh = weldByPosition(readTriangles(path));
    checkSolid(mesh, path);
    if (scale != 1.0)
        mesh = mesh.transformed(scale);
    return mesh;
}

TriangleMesh MeshLoader::readTriangles(const std::string& path) {
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        refuse(path, "no such file");
    // A FIFO or a device would have assimp wait for data forever (or read without end), and a
    // folder is no mesh: only a regular file (or a link to one) is read.
    if (!std::filesystem::is_regular_file(path, error))
        refuse(path, "not a regular file (a folder, FIFO or device), expected a mesh file");
    // assimp calls an empty file unreadable; to the user it is a mesh without triangles.
    if (std::filesystem::file_size(path, error) == 0)
        refuse(path, "contains no triangles");

    Assimp::Importer importer;
    const unsigned flags =
        aiProcess_Triangulate | aiProcess_JoinIdenticalVertices | aiProcess_SortByPType;
    const aiScene* scene = nullptr;
    std::string objText; // kept alive while assimp reads it
    if (ObjText::isObjPath(path)) {
        objText = ObjText::withLeadingZeros(readText(path));
        if (const std::string problem = ObjText::problemIn(objText); !problem.empty())
            refuse(path, "not a valid OBJ file: " + problem);
        scene = importer.ReadFileFromMemory(objText.data(), objText.size(), flags, "obj");
    } else {
        scene = importer.ReadFile(path, flags);
    }
    if (scene == nullptr)
        refuse(path, std::string("cannot read the mesh: ") + importer.GetErrorString());

    TriangleMesh soup;
    if (scene->mRootNode != nullptr)
        appendNode(*scene, *scene->mRootNode, Eigen::Affine3d::Identity(), soup);
    return soup;
}

TriangleMesh MeshLoader::weldByPosition(const TriangleMesh& soup) {
    TriangleMesh welded;
    std::unordered_map<PositionKey, std::uint32_t, PositionHash> indexOf;
    std::vector<std::uint32_t> newIndex(soup.vertices.size());
    for (std::size_t v = 0; v < soup.vertices.size(); ++v) {
        const Vec3d& p = soup.vertices[v];
        const auto [it, inserted] = indexOf.try_emplace(
            PositionKey{p.x(), p.y(), p.z()}, static_cast<std::uint32_t>(welded.vertices.size()));
        if (inserted)
            welded.vertices.push_back(p);
        newIndex[v] = it->second;
    }
    for (const TriangleMesh::Triangle& tri : soup.triangles) {
        const TriangleMesh::Triangle joined{newIndex[tri[0]], newIndex[tri[1]], newIndex[tri[2]]};
        // A triangle with two corners at one position has no area and would count its edge
        // twice, so it goes.
        if (joined[0] != joined[1] && joined[1] != joined[2] && joined[2] != joined[0])
            welded.triangles.push_back(joined);
    }
    return welded;
}

void MeshLoader::checkSolid(TriangleMesh& mesh, const std::string& source) {
    if (mesh.triangles.empty())
        refuse(source, "contains no triangles");
    for (const Vec3d& v : mesh.vertices)
        if (!v.allFinite())
            refuse(source, "has a vertex whose coordinates are not finite numbers");

    const TriangleMesh::EdgeCounts edges = mesh.countEdges();
    if (edges.open > 0)
        refuse(source, "is not closed: " + std::to_string(edges.open) +
                           " edges belong to only one triangle");
    if (edges.nonManifold > 0)
        refuse(source, "is not manifold: " + std::to_string(edges.nonManifold) +
                           " edges belong to more than two triangles");
    if (edges.misoriented > 0)
        refuse(source, "is inconsistently oriented: " + std::to_string(edges.misoriented) +
                           " edges are used twice in the same direction");

    const double volume = mesh.signedVolume();
    const double boxVolume = mesh.bounds().volume();
    // Relative to its box: a closed surface folded flat encloses nothing a body could weigh.
    if (!(std::abs(volume) > 1e-12 * boxVolume))
        refuse(source, "encloses no volume");
    if (volume < 0.0)
        mesh.flipOrientation(); // inside-out, e.g. exported with the other winding convention
}

} // namespace airtrap
