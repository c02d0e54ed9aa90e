#include "cache/FrameFile.h"

#include "cache/BubbleChunk.h"
#include "cache/BubbleSurfacedChunk.h"
#include "cache/BubbleSurroundingsChunk.h"
#include "cache/ByteReader.h"
#include "cache/ByteWriter.h"
#include "cache/FrameValueCheck.h"
#include "cache/PressureSolveChunk.h"
#include "cache/RigidBodyRecord.h"
#include "core/Error.h"

#include <algorithm>
#include <limits>
#include <map>
#include <zlib.h>

namespace airtrap {
namespace {

constexpr char kMagic[4] = {'A', 'T', 'F', '\0'};
// Byte offsets inside the fixed header (docs/CACHE_FORMAT.md, "Frame file").
constexpr std::size_t kVersionOffset = 4;
constexpr std::size_t kHeaderSizeOffset = 8;
constexpr std::size_t kFrameOffset = 12;
constexpr std::size_t kPayloadSizeOffset = 16;
constexpr std::size_t kPayloadCrcOffset = 24;
constexpr std::size_t kHeaderCrcOffset = 28;
constexpr std::size_t kChunkHeaderSize = 12; // 4-byte tag + u64 length

constexpr char kStateTag[] = "STAT";
constexpr char kStatsTag[] = "FSTA";
constexpr char kAttributeTag[] = "PATT";
constexpr char kBodyTag[] = "BODY";
constexpr std::size_t kBodyRecordSize = RigidBodyRecord::kSize;

[[noreturn]] void corruptFrame(const std::string& path, const std::string& what) {
    throw Error(ErrorKind::CacheCorrupt, path + ": " + what);
}

// ---- encoding ----------------------------------------------------------------------------

//! Writes the tag and a placeholder length; returns where the length goes.
std::size_t beginChunk(ByteWriter& out, const char* tag) {
    out.raw(tag, 4);
    const std::size_t lengthAt = out.size();
    out.u64(0);
    return lengthAt;
}

void endChunk(ByteWriter& out, std::size_t lengthAt) {
    out.patchU64(lengthAt, out.size() - lengthAt - sizeof(std::uint64_t));
}

void writeStateChunk(ByteWriter& out, const SimulationState& state) {
    const std::size_t at = beginChunk(out, kStateTag);
    out.i32(state.frame);
    out.f64(state.time);
    out.u64(state.steps);
    out.f64(state.lastTimeStep);
    out.f64(state.lastMaxAcceleration);
    out.u32(state.nextParticleId);
    out.u64(state.fluid.size());
    endChunk(out, at);
}

void writeStatsChunk(ByteWriter& out, const FrameStats& stats) {
    const std::size_t at = beginChunk(out, kStatsTag);
    out.f64(stats.wallSeconds);
    out.u64(stats.stepsInFrame);
    out.f64(stats.maxSpeed);
    out.f64(stats.meanDensity);
    out.u32(static_cast<std::uint32_t>(stats.phaseSeconds.size()));
    for (const auto& [name, seconds] : stats.phaseSeconds) {
        out.string(name);
        out.f64(seconds);
    }
    endChunk(out, at);
}

void writeAttributeChunk(ByteWriter& out, const ParticleAttribute& attribute, std::size_t count) {
    const std::size_t at = beginChunk(out, kAttributeTag);
    out.string(attribute.name);
    out.u8(static_cast<std::uint8_t>(attribute.type));
    out.u64(count);
    out.raw(attribute.data, count * attributeElementSize(attribute.type));
    endChunk(out, at);
}

//! Written only when there are bodies, so frames of body-free scenes stay byte-identical to
//! those written before the chunk existed.
void writeBodyChunk(ByteWriter& out, const std::vector<RigidBodyState>& bodies) {
    const std::size_t at = beginChunk(out, kBodyTag);
    out.u32(static_cast<std::uint32_t>(bodies.size()));
    for (const RigidBodyState& body : bodies)
        RigidBodyRecord::write(out, body);
    endChunk(out, at);
}

void writeBubbleChunk(ByteWriter& out, const SimulationState& state, const FrameStats& stats) {
    const std::size_t at = beginChunk(out, BubbleChunk::kTag);
    BubbleChunk::write(out, state.bubbles, state.nextBubbleId, state.bubblesDeleted, stats.bubbles);
    endChunk(out, at);
    const std::size_t surfacedAt = beginChunk(out, BubbleSurfacedChunk::kTag);
    BubbleSurfacedChunk::write(out, state.bubblesDeleted, stats.bubbles);
    endChunk(out, surfacedAt);
}

//! Written with BUBL whenever bubbles are alive.
void writeBubbleSurroundingsChunk(ByteWriter& out, const std::vector<BubbleState>& bubbles) {
    const std::size_t at = beginChunk(out, BubbleSurroundingsChunk::kTag);
    BubbleSurroundingsChunk::write(out, bubbles);
    endChunk(out, at);
}

template <typename T>
void put(std::vector<std::uint8_t>& bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
}

void writeHeader(std::vector<std::uint8_t>& bytes, int frame) {
    const std::size_t payloadSize = bytes.size() - kFrameHeaderSize;
    std::memcpy(bytes.data(), kMagic, sizeof kMagic);
    put<std::uint32_t>(bytes, kVersionOffset, kFrameFormatVersion);
    put<std::uint32_t>(bytes, kHeaderSizeOffset, kFrameHeaderSize);
    put<std::int32_t>(bytes, kFrameOffset, frame);
    put<std::uint64_t>(bytes, kPayloadSizeOffset, payloadSize);
    put<std::uint32_t>(bytes, kPayloadCrcOffset,
                       computeCrc32(bytes.data() + kFrameHeaderSize, payloadSize));
    put<std::uint32_t>(bytes, kHeaderCrcOffset, computeCrc32(bytes.data(), kHeaderCrcOffset));
}

// ---- decoding ----------------------------------------------------------------------------

struct Header {
    std::uint32_t version = 0;
    std::uint32_t headerSize = 0;
    std::int32_t frame = 0;
    std::uint64_t payloadSize = 0;
    std::uint32_t payloadCrc = 0;
    std::uint32_t headerCrc = 0;
};

struct Chunk {
    std::string tag;
    const std::uint8_t* data;
    std::uint64_t size;
};

//! One PATT chunk before its bytes are copied into the particle set.
struct AttributeChunk {
    AttributeType type;
    std::uint64_t count;
    const std::uint8_t* data;
};

template <typename T>
T get(const std::vector<std::uint8_t>& bytes, std::size_t offset) {
    T value;
    std::memcpy(&value, bytes.data() + offset, sizeof value);
    return value;
}

std::string printableTag(const std::uint8_t* tag) {
    std::string text(reinterpret_cast<const char*>(tag), 4);
    for (char& c : text)
        if (c < 0x20 || c > 0x7e)
            c = '?';
    return text;
}

//! Checks magic, header checksum, version and sizes, in the order that gives the most useful
//! message: a flipped version byte is "corrupt", not "written by a newer Airtrap".
Header readHeader(const std::vector<std::uint8_t>& bytes, const std::string& path) {
    if (bytes.size() < kFrameHeaderSize)
        corruptFrame(path, "truncated: expected at least " + std::to_string(kFrameHeaderSize) +
                               " bytes, found " + std::to_string(bytes.size()));
    if (std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        corruptFrame(path, "not an Airtrap frame file (wrong magic)");
    Header header;
    header.headerCrc = get<std::uint32_t>(bytes, kHeaderCrcOffset);
    if (computeCrc32(bytes.data(), kHeaderCrcOffset) != header.headerCrc)
        corruptFrame(path, "checksum mismatch in the header");
    header.version = get<std::uint32_t>(bytes, kVersionOffset);
    if (header.version > kFrameFormatVersion)
        corruptFrame(path, "written by a newer Airtrap (frame format version " +
                               std::to_string(header.version) + ", this build reads up to " +
                               std::to_string(kFrameFormatVersion) + ")");
    header.headerSize = get<std::uint32_t>(bytes, kHeaderSizeOffset);
    if (header.version == 0 || header.headerSize != kFrameHeaderSize)
        corruptFrame(path, "invalid header (version " + std::to_string(header.version) +
                               ", header size " + std::to_string(header.headerSize) + ")");
    header.frame = get<std::int32_t>(bytes, kFrameOffset);
    header.payloadSize = get<std::uint64_t>(bytes, kPayloadSizeOffset);
    header.payloadCrc = get<std::uint32_t>(bytes, kPayloadCrcOffset);
    return header;
}

void checkPayload(const std::vector<std::uint8_t>& bytes, const Header& header,
                  const std::string& path) {
    const std::uint64_t available = bytes.size() - kFrameHeaderSize;
    if (header.payloadSize > available)
        corruptFrame(path, "truncated: expected " +
                               std::to_string(kFrameHeaderSize + header.payloadSize) +
                               " bytes, found " + std::to_string(bytes.size()));
    if (header.payloadSize < available)
        corruptFrame(path, "unexpected trailing data: expected " +
                               std::to_string(kFrameHeaderSize + header.payloadSize) +
                               " bytes, found " + std::to_string(bytes.size()));
    if (computeCrc32(bytes.data() + kFrameHeaderSize, header.payloadSize) != header.payloadCrc)
        corruptFrame(path, "checksum mismatch in the frame data");
}

std::vector<Chunk> splitChunks(const std::vector<std::uint8_t>& bytes, const std::string& path) {
    std::vector<Chunk> chunks;
    ByteReader reader(bytes.data() + kFrameHeaderSize, bytes.size() - kFrameHeaderSize,
                      path + ": chunk list");
    while (reader.remaining() > 0) {
        if (reader.remaining() < kChunkHeaderSize)
            corruptFrame(path, "incomplete chunk header at payload offset " +
                                   std::to_string(reader.position()));
        const std::string tag = printableTag(reader.take(4));
        const std::uint64_t size = reader.u64();
        if (size > reader.remaining())
            corruptFrame(path, "chunk " + tag + " is " + std::to_string(size) + " bytes, only " +
                                   std::to_string(reader.remaining()) + " remain");
        chunks.push_back({tag, reader.take(size), size});
    }
    return chunks;
}

//! The STAT scalars; returns the particle count, which every PATT chunk must match.
std::uint64_t readStateChunk(const Chunk& chunk, SimulationState& state, const std::string& path) {
    // Bytes after the known fields are fields added by a later version; they are ignored.
    ByteReader in(chunk.data, chunk.size, path + ": chunk STAT");
    state.frame = in.i32();
    state.time = in.f64();
    state.steps = in.u64();
    state.lastTimeStep = in.f64();
    state.lastMaxAcceleration = in.f64();
    state.nextParticleId = in.u32();
    return in.u64();
}

void readStatsChunk(const Chunk& chunk, FrameStats& stats, const std::string& path) {
    ByteReader in(chunk.data, chunk.size, path + ": chunk FSTA");
    stats.wallSeconds = in.f64();
    stats.stepsInFrame = in.u64();
    stats.maxSpeed = in.f64();
    stats.meanDensity = in.f64();
    const std::uint32_t phases = in.u32();
    for (std::uint32_t i = 0; i < phases; ++i) {
        std::string name = in.string();
        const double seconds = in.f64();
        if (!stats.phaseSeconds.emplace(std::move(name), seconds).second)
            corruptFrame(path, "chunk FSTA lists a phase twice");
    }
}

//! Unlike STAT, the body has no room for appended fields: its size is checked exactly, so a
//! damaged count is caught. Per-body fields of a later version go in a chunk of their own.
void readBodyChunk(const Chunk& chunk, std::vector<RigidBodyState>& bodies,
                   const std::string& path) {
    ByteReader in(chunk.data, chunk.size, path + ": chunk BODY");
    const std::uint32_t count = in.u32();
    const std::uint64_t expected = sizeof(std::uint32_t) + std::uint64_t(count) * kBodyRecordSize;
    if (chunk.size != expected)
        corruptFrame(path, "chunk BODY is " + std::to_string(chunk.size) + " bytes, expected " +
                               std::to_string(expected) + " for " + std::to_string(count) +
                               " bodies");
    bodies.reserve(count);
    for (std::uint32_t i = 0; i < count; ++i)
        bodies.push_back(RigidBodyRecord::read(in));
}

void readAttributeChunk(const Chunk& chunk, std::map<std::string, AttributeChunk>& attributes,
                        const std::string& path) {
    ByteReader in(chunk.data, chunk.size, path + ": chunk PATT");
    const std::string name = in.string();
    const auto type = static_cast<AttributeType>(in.u8());
    const std::uint64_t count = in.u64();
    const std::size_t elementSize = attributeElementSize(type);
    const std::string what = "attribute '" + name + "'";
    // An unknown type is fine for an attribute this build does not know (it is skipped), but its
    // size must still add up so that corruption is not mistaken for a newer file.
    if (elementSize != 0 &&
        (count > in.remaining() / elementSize || count * elementSize != in.remaining()))
        corruptFrame(path, what + ": " + std::to_string(count) + " elements do not fit its " +
                               std::to_string(in.remaining()) + " bytes");
    if (!attributes.emplace(name, AttributeChunk{type, count, in.take(in.remaining())}).second)
        corruptFrame(path, what + " appears twice");
}

//! Checks every attribute this build knows against the file before anything is allocated.
void checkAttributes(const std::map<std::string, AttributeChunk>& attributes,
                     std::uint64_t particleCount, const std::string& path) {
    for (const auto& [name, chunk] : attributes)
        if (chunk.count != particleCount)
            corruptFrame(path, "attribute '" + name + "' has " + std::to_string(chunk.count) +
                                   " elements, the frame has " + std::to_string(particleCount) +
                                   " particles");
    for (const ParticleAttribute& expected : ParticleSet().attributes()) {
        const auto found = attributes.find(expected.name);
        if (found == attributes.end())
            corruptFrame(path, "attribute '" + expected.name + "' is missing");
        if (found->second.type != expected.type)
            corruptFrame(path, "attribute '" + expected.name + "' has type " +
                                   std::to_string(static_cast<int>(found->second.type)) +
                                   ", expected " + std::to_string(static_cast<int>(expected.type)));
    }
}

void fillParticles(ParticleSet& fluid, const std::map<std::string, AttributeChunk>& attributes,
                   std::uint64_t particleCount) {
    fluid.resize(static_cast<std::size_t>(particleCount));
    for (const ParticleAttribute& attribute : fluid.attributes()) {
        const std::size_t bytes = fluid.size() * attributeElementSize(attribute.type);
        if (bytes > 0)
            std::memcpy(attribute.data, attributes.at(attribute.name).data, bytes);
    }
}

//! Decodes the chunks into `frame`; unknown tags are skipped (added by a later version).
void readChunks(const std::vector<Chunk>& chunks, FrameData& frame, const std::string& path) {
    std::map<std::string, AttributeChunk> attributes;
    std::uint64_t particleCount = 0;
    int stateChunks = 0;
    int statsChunks = 0;
    int bodyChunks = 0;
    int bubbleChunks = 0;
    int surfacedChunks = 0;
    const Chunk* surroundings = nullptr;
    const Chunk* pressureSolve = nullptr;
    for (const Chunk& chunk : chunks) {
        if (chunk.tag == kStateTag) {
            particleCount = readStateChunk(chunk, frame.state, path);
            ++stateChunks;
        } else if (chunk.tag == kStatsTag) {
            readStatsChunk(chunk, frame.stats, path);
            ++statsChunks;
        } else if (chunk.tag == kAttributeTag) {
            readAttributeChunk(chunk, attributes, path);
        } else if (chunk.tag == kBodyTag) {
            if (++bodyChunks > 1)
                corruptFrame(path, "more than one BODY chunk");
            readBodyChunk(chunk, frame.state.bodies, path);
        } else if (chunk.tag == BubbleChunk::kTag) {
            if (++bubbleChunks > 1)
                corruptFrame(path, "more than one BUBL chunk");
            BubbleChunk::read(chunk.data, chunk.size, path,
                              {frame.state.bubbles, frame.state.nextBubbleId,
                               frame.state.bubblesDeleted, frame.stats.bubbles});
        } else if (chunk.tag == BubbleSurfacedChunk::kTag) {
            if (++surfacedChunks > 1)
                corruptFrame(path, "more than one BSFD chunk");
            BubbleSurfacedChunk::read(chunk.data, chunk.size, path, frame.state.bubblesDeleted,
                                      frame.stats.bubbles);
        } else if (chunk.tag == BubbleSurroundingsChunk::kTag) {
            if (surroundings)
                corruptFrame(path, "more than one BSUR chunk");
            surroundings = &chunk;
        } else if (chunk.tag == PressureSolveChunk::kTag) {
            if (pressureSolve)
                corruptFrame(path, "more than one PSOL chunk");
            pressureSolve = &chunk;
        }
    }
    // After the loop: the surroundings belong to the bubbles of BUBL, wherever it stands.
    if (surroundings)
        BubbleSurroundingsChunk::read(surroundings->data, surroundings->size, path,
                                      frame.state.bubbles);
    if (stateChunks != 1 || statsChunks != 1)
        corruptFrame(path, "expected one STAT and one FSTA chunk, found " +
                               std::to_string(stateChunks) + " and " + std::to_string(statsChunks));
    checkAttributes(attributes, particleCount, path);
    fillParticles(frame.state.fluid, attributes, particleCount);
    if (pressureSolve)
        PressureSolveChunk::read(pressureSolve->data, pressureSolve->size, path,
                                 frame.state.fluid.size(), frame.state.warmStart, frame.stats);
}

} // namespace

std::uint32_t computeCrc32(const void* data, std::size_t size) {
    // zlib takes uInt lengths; feed large buffers in pieces.
    uLong crc = ::crc32(0L, Z_NULL, 0);
    const auto* bytes = static_cast<const Bytef*>(data);
    while (size > 0) {
        const auto piece =
            static_cast<uInt>(std::min<std::size_t>(size, std::numeric_limits<uInt>::max()));
        crc = ::crc32(crc, bytes, piece);
        bytes += piece;
        size -= piece;
    }
    return static_cast<std::uint32_t>(crc);
}

std::vector<std::uint8_t> encodeFrame(const SimulationState& state, const FrameStats& stats) {
    // attributes() only hands out pointers; it is non-const because writers use the same views.
    auto& fluid = const_cast<ParticleSet&>(state.fluid);
    const std::vector<ParticleAttribute> attributes = fluid.attributes();
    std::size_t estimate =
        kFrameHeaderSize + 1024 + state.bodies.size() * kBodyRecordSize +
        state.bubbles.size() * (BubbleChunk::kRecordSize + BubbleSurroundingsChunk::kRecordSize);
    for (const ParticleAttribute& attribute : attributes)
        estimate += kChunkHeaderSize + 64 + fluid.size() * attributeElementSize(attribute.type);
    std::vector<std::uint8_t> bytes(kFrameHeaderSize); // header filled once the payload is known
    bytes.reserve(estimate);
    ByteWriter out(bytes);
    writeStateChunk(out, state);
    writeStatsChunk(out, stats);
    for (const ParticleAttribute& attribute : attributes)
        writeAttributeChunk(out, attribute, fluid.size());
    if (!state.bodies.empty())
        writeBodyChunk(out, state.bodies);
    if (BubbleChunk::needed(state.bubbles, state.nextBubbleId))
        writeBubbleChunk(out, state, stats);
    if (!state.bubbles.empty())
        writeBubbleSurroundingsChunk(out, state.bubbles);
    if (PressureSolveChunk::needed(state.warmStart, stats)) {
        const std::size_t at = beginChunk(out, PressureSolveChunk::kTag);
        PressureSolveChunk::write(out, state.warmStart, stats);
        endChunk(out, at);
    }
    writeHeader(bytes, state.frame);
    return bytes;
}

FrameData decodeFrame(const std::vector<std::uint8_t>& bytes, const std::string& pathForMessages) {
    const Header header = readHeader(bytes, pathForMessages);
    checkPayload(bytes, header, pathForMessages);
    FrameData frame;
    readChunks(splitChunks(bytes, pathForMessages), frame, pathForMessages);
    checkFrameValuesAreFinite(frame, pathForMessages);
    if (frame.state.frame != header.frame)
        corruptFrame(pathForMessages, "header says frame " + std::to_string(header.frame) +
                                          ", data says frame " + std::to_string(frame.state.frame));
    return frame;
}

} // namespace airtrap
