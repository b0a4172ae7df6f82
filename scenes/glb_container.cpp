#include "scenes/glb_container.h"

#include "config/error.h"

#include <cstdint>
#include <cstdio>
#include <cstring>

namespace cavewall::scenes {
namespace {

constexpr std::uint32_t kJsonChunk = 0x4E4F534Au;  // "JSON" read as a little-endian word
constexpr std::uint32_t kBinChunk = 0x004E4942u;   // "BIN\0"

std::uint32_t word(std::string_view bytes, std::size_t at) {
    std::uint32_t v = 0;
    std::memcpy(&v, bytes.data() + at, 4);  // GLB is little-endian, as every target we build for
    return v;
}

std::string hex(std::uint32_t v) {
    char text[16];
    std::snprintf(text, sizeof text, "0x%08X", v);
    return text;
}

[[noreturn]] void fail(const std::string& file, const std::string& part, std::size_t at, const std::string& what) {
    throw Error(file + ": GLB " + part + " at byte " + std::to_string(at) + ": " + what);
}

}  // namespace

GlbChunks splitGlb(std::string_view bytes, const std::string& file) {
    const std::size_t size = bytes.size();
    if (size < 12)
        fail(file, "header", 0,
             "the file is truncated (expected 12 bytes of header, got " + std::to_string(size) + ")");
    if (bytes.substr(0, 4) != "glTF") fail(file, "header", 0, "expected the magic 'glTF', got " + hex(word(bytes, 0)));
    if (word(bytes, 4) != 2)
        fail(file, "header", 4, "unsupported version (expected 2, got " + std::to_string(word(bytes, 4)) + ")");
    const std::uint64_t length = word(bytes, 8);
    if (length > size)
        fail(file, "header", 8,
             "total length is " + std::to_string(length) + " but the file has " + std::to_string(size) +
                 " bytes (expected at most " + std::to_string(size) + "; the file is truncated)");
    if (length < 20)
        fail(file, "chunk 0 (JSON)", 12,
             "no room for a chunk header (expected a total length of at least 20, got " + std::to_string(length) + ")");
    const std::uint64_t jsonLength = word(bytes, 12);
    if (word(bytes, 16) != kJsonChunk)
        fail(file, "chunk 0", 16,
             "wrong chunk type (expected " + hex(kJsonChunk) + ", JSON, got " + hex(word(bytes, 16)) + ")");
    if (jsonLength == 0) fail(file, "chunk 0 (JSON)", 12, "empty JSON chunk (expected a length of at least 1, got 0)");
    if (20 + jsonLength > length)
        fail(file, "chunk 0 (JSON)", 12,
             "length " + std::to_string(jsonLength) + " runs past the end (expected at most " +
                 std::to_string(length - 20) + " bytes after the chunk header)");
    GlbChunks out;
    out.json = bytes.substr(20, jsonLength);
    const std::uint64_t binAt = 20 + jsonLength;
    if (binAt == length) return out;
    if (binAt + 8 > length)
        fail(file, "chunk 1 (BIN)", binAt,
             "truncated chunk header (expected 8 bytes, got " + std::to_string(length - binAt) + ")");
    const std::uint64_t binLength = word(bytes, binAt);
    if (word(bytes, binAt + 4) != kBinChunk)
        fail(file, "chunk 1", binAt + 4,
             "wrong chunk type (expected " + hex(kBinChunk) + ", BIN, got " + hex(word(bytes, binAt + 4)) + ")");
    if (binLength < 4 || binLength % 4 != 0)
        fail(file, "chunk 1 (BIN)", binAt,
             "bad length (expected a multiple of 4 of at least 4, got " + std::to_string(binLength) + ")");
    if (binAt + 8 + binLength > length)
        fail(file, "chunk 1 (BIN)", binAt,
             "length " + std::to_string(binLength) + " runs past the end (expected at most " +
                 std::to_string(length - binAt - 8) + " bytes after the chunk header)");
    out.bin = bytes.substr(binAt + 8, binLength);
    out.hasBin = true;
    return out;
}

}  // namespace cavewall::scenes
