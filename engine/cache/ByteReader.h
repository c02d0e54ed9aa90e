#pragma once
// Reads little-endian binary values from a byte range, bounds-checked: running past the end is a
// corrupt file, reported with the file and section, never a read out of bounds.
#include "cache/ByteWriter.h"
#include "core/Error.h"

#include <bit>
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>

namespace airtrap {

class ByteReader {
public:
    //! `context` names the file and section in messages, e.g. "/c/frame_0003.atf: chunk STAT".
    ByteReader(const std::uint8_t* data, std::size_t size, std::string context)
        : data_(data), size_(size), context_(std::move(context)) {}

    std::uint8_t u8() { return value<std::uint8_t>(); }
    std::uint32_t u32() { return value<std::uint32_t>(); }
    std::int32_t i32() { return value<std::int32_t>(); }
    std::uint64_t u64() { return value<std::uint64_t>(); }
    double f64() { return std::bit_cast<double>(u64()); }
    std::string string() {
        const std::uint32_t length = u32();
        const std::uint8_t* bytes = take(length);
        return std::string(reinterpret_cast<const char*>(bytes), length);
    }
    //! Returns a pointer to the next `count` bytes and moves past them.
    const std::uint8_t* take(std::uint64_t count) {
        if (count > remaining())
            throw Error(ErrorKind::CacheCorrupt, context_ + ": needs " + std::to_string(count) +
                                                     " more bytes, has " +
                                                     std::to_string(remaining()));
        const std::uint8_t* at = data_ + position_;
        position_ += static_cast<std::size_t>(count);
        return at;
    }
    std::size_t remaining() const { return size_ - position_; }
    std::size_t position() const { return position_; }
    const std::string& context() const { return context_; }

private:
    template <typename T>
    T value() {
        T result;
        std::memcpy(&result, take(sizeof(T)), sizeof(T));
        return result;
    }

    const std::uint8_t* data_;
    std::size_t size_;
    std::size_t position_ = 0;
    std::string context_;
};

} // namespace airtrap
