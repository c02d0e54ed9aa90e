#pragma once
// Appends little-endian binary values to a byte buffer. The frame format is little-endian and so
// is every host we build for (checked below), so values are copied as they are in memory; floats
// and doubles keep their exact bit patterns, which is what makes a resumed bake bit-identical.
#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace airtrap {

static_assert(std::endian::native == std::endian::little,
              "the frame cache format is little-endian; a big-endian host needs byte swapping");

class ByteWriter {
public:
    explicit ByteWriter(std::vector<std::uint8_t>& out) : out_(out) {}

    void u8(std::uint8_t value) { raw(&value, sizeof value); }
    void u32(std::uint32_t value) { raw(&value, sizeof value); }
    void i32(std::int32_t value) { raw(&value, sizeof value); }
    void u64(std::uint64_t value) { raw(&value, sizeof value); }
    void f64(double value) { u64(std::bit_cast<std::uint64_t>(value)); }
    //! A u32 byte count followed by the bytes (no terminator).
    void string(const std::string& text) {
        u32(static_cast<std::uint32_t>(text.size()));
        raw(text.data(), text.size());
    }
    void raw(const void* data, std::size_t size) {
        if (size == 0)
            return; // data may be null for an empty array
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        out_.insert(out_.end(), bytes, bytes + size);
    }
    //! Overwrites a u64 written earlier (chunk lengths are known only after the chunk body).
    void patchU64(std::size_t offset, std::uint64_t value) {
        std::memcpy(out_.data() + offset, &value, sizeof value);
    }
    std::size_t size() const { return out_.size(); }

private:
    std::vector<std::uint8_t>& out_;
};

} // namespace airtrap
