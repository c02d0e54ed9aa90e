#pragma once
// Helpers the fuzz targets share (docs/TESTING.md "Fuzzing"). The readers refuse a file whose
// checksums do not hold before they parse it, so a mutated file would almost always stop at the
// CRC and the parser behind it would never be reached: the targets give each mutated input the
// checksums it needs first.
#include "cache/FrameFile.h"

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace airtrap::fuzz {

inline std::vector<std::uint8_t> bytesOf(const std::uint8_t* data, std::size_t size) {
    return std::vector<std::uint8_t>(data, data + size);
}

template <class T>
void put(std::vector<std::uint8_t>& bytes, std::size_t offset, T value) {
    std::memcpy(bytes.data() + offset, &value, sizeof value);
}

//! A frame file's header fields that describe its payload (docs/CACHE_FORMAT.md "Header"):
//! the payload's size and CRC-32, then the header's own CRC-32, recomputed for `bytes`.
inline void fixFrameChecksums(std::vector<std::uint8_t>& bytes) {
    constexpr std::size_t kPayloadSizeOffset = 16;
    constexpr std::size_t kPayloadCrcOffset = 24;
    constexpr std::size_t kHeaderCrcOffset = 28;
    if (bytes.size() < kFrameHeaderSize)
        return;
    const std::uint64_t payload = bytes.size() - kFrameHeaderSize;
    put(bytes, kPayloadSizeOffset, payload);
    put(bytes, kPayloadCrcOffset, computeCrc32(bytes.data() + kFrameHeaderSize, payload));
    put(bytes, kHeaderCrcOffset, computeCrc32(bytes.data(), kHeaderCrcOffset));
}

//! The CRC-32 of everything before the last four bytes, written into them (the post stage's
//! mesh and sub-grid files).
inline void fixTrailingChecksum(std::vector<std::uint8_t>& bytes) {
    if (bytes.size() < 4)
        return;
    put(bytes, bytes.size() - 4, computeCrc32(bytes.data(), bytes.size() - 4));
}

} // namespace airtrap::fuzz
