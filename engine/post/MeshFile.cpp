#include "post/MeshFile.h"

#include "cache/ByteReader.h"
#include "cache/FrameFile.h"
#include "core/AtomicFile.h"
#include "core/Error.h"

#include <cstring>

namespace airtrap {

namespace {

constexpr std::uint32_t kMagic = 0x534D5441; // "ATMS" read as little-endian bytes
constexpr std::size_t kHeaderBytes = 4 * sizeof(std::uint32_t);

} // namespace

std::vector<std::uint8_t> MeshFile::encode(const TriangleMesh& mesh) {
    const std::size_t bodyBytes = 12 * (mesh.vertices.size() + mesh.triangles.size());
    std::vector<std::uint8_t> bytes(kHeaderBytes + bodyBytes + sizeof(std::uint32_t));
    std::uint8_t* out = bytes.data();
    const auto put = [&out](const void* data, std::size_t size) {
        std::memcpy(out, data, size);
        out += size;
    };
    const std::uint32_t header[4] = {kMagic, kFormatVersion, std::uint32_t(mesh.vertices.size()),
                                     std::uint32_t(mesh.triangles.size())};
    put(header, sizeof header);
    for (const Vec3d& v : mesh.vertices) {
        const Vec3f p = v.cast<float>();
        put(p.data(), 3 * sizeof(float));
    }
    for (const TriangleMesh::Triangle& t : mesh.triangles)
        put(t.data(), 3 * sizeof(std::uint32_t));
    const std::uint32_t crc = computeCrc32(bytes.data(), bytes.size() - sizeof crc);
    put(&crc, sizeof crc);
    return bytes;
}

TriangleMesh MeshFile::decode(const std::vector<std::uint8_t>& bytes,
                              const std::string& pathForMessages) {
    const auto corrupt = [&](const std::string& what) {
        return Error(ErrorKind::CacheCorrupt, pathForMessages + ": " + what);
    };
    ByteReader in(bytes.data(), bytes.size(), pathForMessages);
    if (in.u32() != kMagic)
        throw corrupt("not an Airtrap mesh file (no ATMS magic)");
    if (const std::uint32_t version = in.u32(); version > kFormatVersion)
        throw corrupt("mesh format version " + std::to_string(version) + ", this build reads " +
                      std::to_string(kFormatVersion) + " at most");
    const std::uint32_t vertexCount = in.u32();
    const std::uint32_t triangleCount = in.u32();
    const std::uint64_t expected = kHeaderBytes + 12ull * vertexCount + 12ull * triangleCount + 4;
    if (bytes.size() != expected)
        throw corrupt(std::to_string(bytes.size()) + " bytes, its counts need " +
                      std::to_string(expected) + " (truncated?)");
    std::uint32_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - 4, 4);
    if (computeCrc32(bytes.data(), bytes.size() - 4) != stored)
        throw corrupt("checksum mismatch");
    TriangleMesh mesh;
    mesh.vertices.resize(vertexCount);
    for (Vec3d& v : mesh.vertices) {
        Vec3f p;
        std::memcpy(p.data(), in.take(3 * sizeof(float)), 3 * sizeof(float));
        // An exporter writes what it reads: NaN would reach the renderer as "nan" in an OBJ.
        if (!p.allFinite())
            throw corrupt("vertex " + std::to_string(&v - mesh.vertices.data()) +
                          " is not a finite point");
        v = p.cast<double>();
    }
    mesh.triangles.resize(triangleCount);
    for (TriangleMesh::Triangle& t : mesh.triangles) {
        std::memcpy(t.data(), in.take(3 * sizeof(std::uint32_t)), 3 * sizeof(std::uint32_t));
        for (const std::uint32_t index : t)
            if (index >= vertexCount)
                throw corrupt("a triangle uses vertex " + std::to_string(index) + " of " +
                              std::to_string(vertexCount));
    }
    return mesh;
}

void MeshFile::write(const std::string& path, const TriangleMesh& mesh) {
    AtomicFile::write(path, encode(mesh));
}

TriangleMesh MeshFile::read(const std::string& path) {
    return decode(AtomicFile::read(path), path);
}

} // namespace airtrap
