// Writes the fuzz targets' binary seed corpora into the folder given (scripts/fuzz.sh runs it
// first): frames with every chunk (water, bodies, bubbles and their surroundings, the pressure
// solves' warm start), a manifest, a free-surface mesh file and a sub-grid bubble file, made by
// the writers of this build, so the seeds always have the current format. The scene and mesh
// seeds are the samples and the test meshes themselves.
#include "cache/CacheManifest.h"
#include "cache/FrameFile.h"
#include "post/MeshFile.h"
#include "post/SubgridFile.h"

#include <filesystem>
#include <fstream>
#include <iostream>

namespace {

using namespace airtrap;
namespace fs = std::filesystem;

void writeFile(const fs::path& path, const std::vector<std::uint8_t>& bytes) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary)
        .write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
}

BubbleState bubbleAt(std::uint32_t id, const Vec3d& centre) {
    BubbleState bubble;
    bubble.id = id;
    bubble.birthFrame = 2;
    bubble.radius = 0.02;
    bubble.body.position = centre;
    bubble.body.linearVelocity = Vec3d(0.0, 0.2, 0.01);
    bubble.age = 0.1;
    bubble.surroundings.wettedShare = 0.8;
    bubble.surroundings.measured = true;
    return bubble;
}

//! A frame of 27 particles in a 3 × 3 × 3 lattice, with `extras` a body, two bubbles and the
//! divergence-free solver's warm start.
FrameData frameSeed(int frame, bool extras) {
    FrameData data;
    SimulationState& state = data.state;
    state.frame = frame;
    state.time = (frame - 1) / 30.0;
    for (int k = 0; k < 27; ++k)
        state.fluid.push(
            Vec3f(0.1f + 0.02f * (k % 3), 0.1f + 0.02f * (k / 3 % 3), 0.1f + 0.02f * (k / 9)),
            Vec3f(0.0f, -0.1f, 0.0f), 1000.0f, std::uint32_t(k));
    state.nextParticleId = 27;
    data.stats.phaseSeconds = {{"density", 0.01}, {"forces", 0.02}};
    data.stats.stepsInFrame = 5;
    if (extras) {
        RigidBodyState body;
        body.position = Vec3d(0.5, 0.5, 0.5);
        state.bodies.push_back(body);
        state.bubbles = {bubbleAt(0, Vec3d(0.2, 0.1, 0.2)), bubbleAt(1, Vec3d(0.3, 0.1, 0.2))};
        state.nextBubbleId = 2;
        state.warmStart.divergence.assign(27, 0.001f);
        state.warmStart.density.assign(27, 0.5f);
    }
    return data;
}

std::vector<std::uint8_t> withSelector(std::uint8_t selector, std::vector<std::uint8_t> bytes) {
    bytes.insert(bytes.begin(), selector);
    return bytes;
}

} // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::cerr << "usage: airtrap-fuzz-seeds FOLDER\n";
        return 1;
    }
    const fs::path root = argv[1];
    for (const bool extras : {false, true}) {
        const FrameData frame = frameSeed(extras ? 2 : 1, extras);
        writeFile(root / "frame" / (extras ? "frame_extras.atf" : "frame_plain.atf"),
                  encodeFrame(frame.state, frame.stats));
    }
    CacheManifest manifest;
    manifest.scene = {{"format_version", 1}, {"name", "seed"}};
    manifest.parameterHash = "0123456789abcdef";
    manifest.fps = 30.0;
    manifest.frames = {{1, "frame_0001.atf", 1234, 0xdeadbeef}, {2, "frame_0002.atf", 1240, 7}};
    manifest.status = "stopped";
    const std::string manifestText = manifest.toJson().dump(2);
    writeFile(root / "manifest" / "manifest.json",
              std::vector<std::uint8_t>(manifestText.begin(), manifestText.end()));
    TriangleMesh mesh;
    mesh.vertices = {Vec3d::Zero(), Vec3d::UnitX(), Vec3d::UnitY(), Vec3d::UnitZ()};
    mesh.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    writeFile(root / "post-results" / "water.atm", withSelector(0, MeshFile::encode(mesh)));
    SubgridFrame subgrid;
    subgrid.trappedIdsBelow = 2;
    subgrid.nextId = 3;
    for (std::uint32_t id = 0; id < 3; ++id) {
        SubgridBubble bubble;
        bubble.id = id;
        bubble.position = Vec3d(0.1 * id, 0.2, 0.3);
        bubble.radius = 0.002;
        subgrid.bubbles.push_back(bubble);
    }
    writeFile(root / "post-results" / "subgrid.atb", withSelector(1, SubgridFile::encode(subgrid)));
    std::cout << "seeds written to " << root.string() << '\n';
    return 0;
}
