#include "post/SubgridFile.h"

#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"
#include "cache/FrameFile.h"
#include "core/AtomicFile.h"
#include "core/Error.h"

#include <cmath>
#include <cstring>

namespace airtrap {

namespace {

constexpr std::uint32_t kMagic = 0x42535441; // "ATSB" read as little-endian bytes
constexpr std::size_t kHeaderBytes = 5 * sizeof(std::uint32_t);
constexpr std::size_t kBubbleBytes = 3 * sizeof(std::uint32_t) + 8 * sizeof(double);

void writeVector(ByteWriter& out, const Vec3d& v) {
    out.f64(v.x());
    out.f64(v.y());
    out.f64(v.z());
}

Vec3d readVector(ByteReader& in) {
    const double x = in.f64();
    const double y = in.f64();
    return {x, y, in.f64()};
}

void writeBubble(ByteWriter& out, const SubgridBubble& bubble) {
    out.u32(bubble.id);
    out.u32(bubble.parentId);
    out.i32(bubble.generation);
    writeVector(out, bubble.position);
    out.f64(bubble.radius);
    writeVector(out, bubble.velocity);
    out.f64(bubble.age);
}

SubgridBubble readBubble(ByteReader& in) {
    SubgridBubble bubble;
    bubble.id = in.u32();
    bubble.parentId = in.u32();
    bubble.generation = in.i32();
    bubble.position = readVector(in);
    bubble.radius = in.f64();
    bubble.velocity = readVector(in);
    bubble.age = in.f64();
    return bubble;
}

} // namespace

std::vector<std::uint8_t> SubgridFile::encode(const SubgridFrame& frame) {
    std::vector<std::uint8_t> bytes;
    bytes.reserve(kHeaderBytes + kBubbleBytes * frame.bubbles.size() + sizeof(std::uint32_t));
    ByteWriter out(bytes);
    out.u32(kMagic);
    out.u32(kFormatVersion);
    out.u32(frame.trappedIdsBelow);
    out.u32(frame.nextId);
    out.u32(std::uint32_t(frame.bubbles.size()));
    for (const SubgridBubble& bubble : frame.bubbles)
        writeBubble(out, bubble);
    out.u32(computeCrc32(bytes.data(), bytes.size()));
    return bytes;
}

SubgridFrame SubgridFile::decode(const std::vector<std::uint8_t>& bytes,
                                 const std::string& pathForMessages) {
    const auto corrupt = [&](const std::string& what) {
        return Error(ErrorKind::CacheCorrupt, pathForMessages + ": " + what);
    };
    ByteReader in(bytes.data(), bytes.size(), pathForMessages);
    if (in.u32() != kMagic)
        throw corrupt("not an Airtrap sub-grid bubble file (no ATSB magic)");
    if (const std::uint32_t version = in.u32(); version > kFormatVersion)
        throw corrupt("sub-grid format version " + std::to_string(version) + ", this build reads " +
                      std::to_string(kFormatVersion) + " at most");
    SubgridFrame frame;
    frame.trappedIdsBelow = in.u32();
    frame.nextId = in.u32();
    const std::uint32_t count = in.u32();
    const std::uint64_t expected = kHeaderBytes + std::uint64_t(kBubbleBytes) * count + 4;
    if (bytes.size() != expected)
        throw corrupt(std::to_string(bytes.size()) + " bytes, its count needs " +
                      std::to_string(expected) + " (truncated?)");
    std::uint32_t stored = 0;
    std::memcpy(&stored, bytes.data() + bytes.size() - 4, 4);
    if (computeCrc32(bytes.data(), bytes.size() - 4) != stored)
        throw corrupt("checksum mismatch");
    frame.bubbles.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i) {
        frame.bubbles.push_back(readBubble(in));
        const SubgridBubble& bubble = frame.bubbles.back();
        if (!bubble.position.allFinite() || !bubble.velocity.allFinite() ||
            !std::isfinite(bubble.radius) || !(bubble.radius > 0.0) || !std::isfinite(bubble.age))
            throw corrupt("bubble " + std::to_string(i) +
                          " holds a value that is not a finite number (or a radius not above 0)");
    }
    return frame;
}

void SubgridFile::write(const std::string& path, const SubgridFrame& frame) {
    AtomicFile::write(path, encode(frame));
}

SubgridFrame SubgridFile::read(const std::string& path) {
    return decode(AtomicFile::read(path), path);
}

} // namespace airtrap
