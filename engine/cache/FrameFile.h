#pragma once
// One cached frame as bytes (the .atf file, docs/CACHE_FORMAT.md): a fixed 32-byte header, then
// tagged chunks. Decoding checks everything and either returns the whole frame or throws; it
// never returns partial data.
#include "sim/FrameStats.h"
#include "sim/SimulationState.h"

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace airtrap {

//! Everything one frame file holds.
struct FrameData {
    SimulationState state;
    FrameStats stats;

    bool operator==(const FrameData& other) const = default;
};

//! Version written into every frame header; a reader refuses files with a larger one.
inline constexpr std::uint32_t kFrameFormatVersion = 2;
//! Bytes of the fixed header that precedes the chunk payload.
inline constexpr std::uint32_t kFrameHeaderSize = 32;

//! Serialises a frame: header + STAT, FSTA, one PATT chunk per ParticleSet attribute, and BODY
//! when the state has rigid bodies.
std::vector<std::uint8_t> encodeFrame(const SimulationState& state, const FrameStats& stats);

//! Parses and verifies a frame (magic, version, sizes, checksums, attribute counts). Throws
//! Error(CacheCorrupt, "<pathForMessages>: <what is wrong>") on any failure.
FrameData decodeFrame(const std::vector<std::uint8_t>& bytes, const std::string& pathForMessages);

//! CRC-32 with the zlib polynomial (as zlib's crc32()), used by frame files and the manifest.
std::uint32_t computeCrc32(const void* data, std::size_t size);

} // namespace airtrap
