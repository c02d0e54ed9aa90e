#include "io/PlyExporter.h"

#include "core/AtomicFile.h"
#include "io/PlyHeader.h"

#include <cstdio>
#include <cstring>

namespace airtrap {

namespace {

std::string particleHeader(std::size_t count, const std::vector<std::string>& comments) {
    return plyHeader(count, comments,
                     {{"float", "x"},
                      {"float", "y"},
                      {"float", "z"},
                      {"float", "vx"},
                      {"float", "vy"},
                      {"float", "vz"},
                      {"float", "density"},
                      {"uint", "id"}});
}

void append(std::uint8_t*& out, const void* value, std::size_t size) {
    std::memcpy(out, value, size);
    out += size;
}

} // namespace

std::vector<std::uint8_t> PlyExporter::encode(const ParticleSet& particles,
                                              const std::vector<std::string>& comments, UpAxis up) {
    const std::string head = particleHeader(particles.size(), comments);
    std::vector<std::uint8_t> bytes(head.size() + particles.size() * kVertexBytes);
    std::memcpy(bytes.data(), head.data(), head.size());
    std::uint8_t* out = bytes.data() + head.size();
    for (std::size_t i = 0; i < particles.size(); ++i) {
        const Vec3f position =
            toExportAxes(particles.positions[i].cast<double>(), up).cast<float>();
        const Vec3f velocity =
            toExportAxes(particles.velocities[i].cast<double>(), up).cast<float>();
        append(out, position.data(), 3 * sizeof(float));
        append(out, velocity.data(), 3 * sizeof(float));
        append(out, &particles.densities[i], sizeof(float));
        append(out, &particles.ids[i], sizeof(std::uint32_t));
    }
    return bytes;
}

void PlyExporter::write(const std::string& path, const ParticleSet& particles,
                        const std::vector<std::string>& comments, UpAxis up) {
    AtomicFile::write(path, encode(particles, comments, up));
}

std::string PlyExporter::fileName(int frame) {
    char name[32];
    std::snprintf(name, sizeof name, "particles_%04d.ply", frame);
    return name;
}

} // namespace airtrap
