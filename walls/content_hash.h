#pragma once
// The content check of the bake cache's files (wall textures flat and depth, ".bct" and ".tx",
// cluster impostors): a 64-bit hash of a file's bytes, recorded when the file is written and
// compared when it is read for drawing. GL-free.
//
// The hash is XXH64 (Collet's xxHash, 64-bit variant), written from its published description:
// four 64-bit lanes over 32-byte stripes, then the tail, then the avalanche; it gives the
// published values (tests/walls/content_hash_test.cpp). It is not a cryptographic hash: it
// catches torn, flipped, swapped and replaced files, not someone forging one. On the plant's
// BC1 textures it reads about 3x faster than zlib's crc32 and 14x faster than byte-wise FNV-1a
// (bench/cache_check_bench.cpp), so checking a file costs little next to inflating it.

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace cavewall::walls {

// XXH64 of `bytes` with `seed`.
std::uint64_t contentHash(std::string_view bytes, std::uint64_t seed = 0);

// Every byte of `file` (one read); nullopt when it cannot be opened or read in full.
std::optional<std::string> readFileBytes(const std::filesystem::path& file);

// contentHash of a file's bytes; nullopt when the file cannot be read.
std::optional<std::uint64_t> contentHashFile(const std::filesystem::path& file);

}  // namespace cavewall::walls
