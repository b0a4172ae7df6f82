#include "walls/content_hash.h"

#include <bit>
#include <cstdio>
#include <cstring>

namespace cavewall::walls {

namespace {

constexpr std::uint64_t kP1 = 0x9E3779B185EBCA87ull;
constexpr std::uint64_t kP2 = 0xC2B2AE3D27D4EB4Full;
constexpr std::uint64_t kP3 = 0x165667B19E3779F9ull;
constexpr std::uint64_t kP4 = 0x85EBCA77C2B2AE63ull;
constexpr std::uint64_t kP5 = 0x27D4EB2F165667C5ull;

constexpr std::uint64_t rotl(std::uint64_t x, int r) { return (x << r) | (x >> (64 - r)); }

// Little-endian loads (the specification's byte order; this code builds on little-endian hosts).
std::uint64_t read64(const unsigned char* p) {
    std::uint64_t v;
    std::memcpy(&v, p, 8);
    return v;
}
std::uint32_t read32(const unsigned char* p) {
    std::uint32_t v;
    std::memcpy(&v, p, 4);
    return v;
}

std::uint64_t round(std::uint64_t acc, std::uint64_t lane) { return rotl(acc + lane * kP2, 31) * kP1; }
std::uint64_t merge(std::uint64_t acc, std::uint64_t lane) { return (acc ^ round(0, lane)) * kP1 + kP4; }

}  // namespace

std::uint64_t contentHash(std::string_view bytes, std::uint64_t seed) {
    static_assert(std::endian::native == std::endian::little, "contentHash reads lanes little-endian");
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    const unsigned char* const end = p + bytes.size();
    std::uint64_t h;
    if (bytes.size() >= 32) {
        std::uint64_t v1 = seed + kP1 + kP2, v2 = seed + kP2, v3 = seed, v4 = seed - kP1;
        for (; end - p >= 32; p += 32) {
            v1 = round(v1, read64(p));
            v2 = round(v2, read64(p + 8));
            v3 = round(v3, read64(p + 16));
            v4 = round(v4, read64(p + 24));
        }
        h = rotl(v1, 1) + rotl(v2, 7) + rotl(v3, 12) + rotl(v4, 18);
        h = merge(merge(merge(merge(h, v1), v2), v3), v4);
    } else {
        h = seed + kP5;
    }
    h += bytes.size();
    for (; end - p >= 8; p += 8) h = rotl(h ^ round(0, read64(p)), 27) * kP1 + kP4;
    if (end - p >= 4) {
        h = rotl(h ^ (read32(p) * kP1), 23) * kP2 + kP3;
        p += 4;
    }
    for (; p < end; ++p) h = rotl(h ^ (*p * kP5), 11) * kP1;
    h ^= h >> 33;
    h *= kP2;
    h ^= h >> 29;
    h *= kP3;
    h ^= h >> 32;
    return h;
}

std::optional<std::string> readFileBytes(const std::filesystem::path& file) {
    std::FILE* f = std::fopen(file.c_str(), "rb");
    if (!f) return std::nullopt;
    std::string bytes;
    std::error_code ec;
    const std::uintmax_t size = std::filesystem::file_size(file, ec);
    // One read of the size found; a file that grew or shrank meanwhile is read to its end.
    bytes.resize(ec ? 0 : static_cast<std::size_t>(size) + 1);
    std::size_t got = std::fread(bytes.data(), 1, bytes.size(), f);
    while (got == bytes.size() && !std::ferror(f)) {
        bytes.resize(bytes.size() * 2 + 4096);
        got += std::fread(bytes.data() + got, 1, bytes.size() - got, f);
    }
    const bool ok = !std::ferror(f);
    std::fclose(f);
    if (!ok) return std::nullopt;
    bytes.resize(got);
    return bytes;
}

std::optional<std::uint64_t> contentHashFile(const std::filesystem::path& file) {
    const std::optional<std::string> bytes = readFileBytes(file);
    if (!bytes) return std::nullopt;
    return contentHash(*bytes);
}

}  // namespace cavewall::walls
