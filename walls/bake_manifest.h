#pragma once
// The baked wall textures of a scene on disk: one folder per bake key holding manifest.json and
// one tiled, MIP-mapped image file per texture (written by walls/gl/baker.h).
//
// manifest.json:
//   {"version": 3, "key": "<16 hex digits>", "alphaDeg": 10,
//    "textures": [{"id": 0, "cell": 0, "wall": 0, "samplingPoint": [x, y, z],
//                  "resolution": [w, h], "texture": "<16 hex>", "file": "tex_0000_<16 hex>.bct",
//                  "bytes": 123, "hash": "<16 hex>", "mtimeNs": 1796212345123456789,
//                  "inode": 1234, "check": "<16 hex>",
//                  "depth": {"file": "tex_0000_<16 hex>.depth.tif", "bytes": 45,
//                            "hash": "<16 hex>", "range": [near, far], "check": "<16 hex>"}}]}
// ("depth" only for depth walls, walls/depth_file.h; the texture is valid when both files are.)
// `key` is a content hash of everything the textures depend on (scene files, plan, bake
// settings). `hash` is the content check of the file's bytes (walls/content_hash.h, XXH64),
// recorded when the file is written and compared whenever the file is read for drawing: a
// texture is valid when its file exists with exactly `bytes` bytes and that hash; anything else
// (missing, torn, flipped, replaced, swapped) is re-baked and never drawn. Manifests are written
// atomically (temporary file + rename), and after every texture file they list, so a manifest
// never names a file that was not complete.
//
// Which texture an entry is for: `texture` is the texture key (walls/bake_key.h) that its file
// name carries too, and the id in the file name must be the entry's `id`. `check` is a hash of
// the entry's own fields (id, cell, wall, sampling point, resolution, file, bytes, hash, and
// the depth block's check, or that there is none); the depth block's `check` covers its file,
// bytes, hash and range and the texture's id and file. An entry whose checks fail on reading
// (an edited range, a deleted depth block, a file name pointed at another texture's) is dropped
// and reported in BakeManifest::rejected: it is re-baked, never drawn.
//
// Stamps: `mtimeNs` and `inode` are the file's last-write time (ns since the Unix epoch) and
// inode number when its bytes were last hashed. A run starting up may trust a file whose size,
// time and inode still equal the manifest's (textureFileUnchanged: one stat, no read), because
// the texture pager (walls/texture_pager.h) checks the hash of every file it pages in anyway;
// `cavewall bake` hashes every listed file. Manifests of versions 1 and 2 (an older hash, no
// checks) read with `version` set: their textures are stale and re-baked.

#include "config/error.h"
#include "walls/content_hash.h"

#include <glm/glm.hpp>

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::walls {

struct BakedTexture {
    int id = 0;  // Plan texture id
    int cell = 0, wall = 0;
    glm::dvec3 samplingPoint{0.0};
    glm::ivec2 resolution{0, 0};
    std::string file;  // relative to the manifest's folder
    std::uint64_t bytes = 0;
    std::uint64_t hash = 0;    // contentHash of the file's bytes (walls/content_hash.h)
    std::int64_t mtimeNs = 0;  // last-write time when the hash was checked; 0: unknown
    std::uint64_t inode = 0;   // inode number then
    // Depth walls only (walls/depth_file.h): the depth file beside `file`, its size and hash,
    // and the range of its finite depths (metres behind the wall). Empty for flat walls.
    std::string depthFile{};
    std::uint64_t depthBytes = 0;
    std::uint64_t depthHash = 0;
    glm::dvec2 depthRange{0.0};
    bool operator==(const BakedTexture&) const = default;
};

// The manifest version written; older ones read (see above).
inline constexpr int kManifestVersion = 3;

struct BakeManifest {
    std::uint64_t key = 0;
    double alphaDeg = 0.0;
    std::vector<BakedTexture> textures;  // sorted by id
    int version = kManifestVersion;      // as read; < kManifestVersion: every texture is stale
    // Read only: one message per entry dropped because its checks failed ("<file>: textures[3]
    // ("tex_0003_....bct"): its check does not match its fields (expected ..., got ...)").
    std::vector<std::string> rejected{};
    bool operator==(const BakeManifest&) const = default;
};

// The checks written with an entry (see above): of its depth block, and of the whole entry.
std::uint64_t depthCheck(const BakedTexture& texture);
std::uint64_t entryCheck(const BakedTexture& texture);

// FNV-1a 64-bit hash (bake keys, walls/bake_key.h), incremental: pass the previous result as `seed` to continue.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ull);
// fnv1a of a file (bake keys of scene files); throws Error when unreadable.
std::uint64_t hashFile(const std::filesystem::path& file);
std::string hex64(std::uint64_t value);  // 16 lower-case hex digits

std::string manifestToJson(const BakeManifest& manifest);
// Throws Error naming `source` and the JSON path on bad input.
BakeManifest manifestFromJson(std::string_view text, const std::string& source);

// Reads <folder>/manifest.json; nullopt-like empty manifest (key 0) when there is none.
BakeManifest readManifest(const std::filesystem::path& folder);
// Writes <folder>/manifest.json atomically.
void writeManifest(const std::filesystem::path& folder, const BakeManifest& manifest);
// Writes bytes to `file` atomically (scenes::writeAtomically).
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

// True when the texture's file (and its depth file, if any) exists with the recorded size and
// content hash (each file read once).
bool textureFileValid(const std::filesystem::path& folder, const BakedTexture& texture);
// Why textureFileValid is false, naming the file ("<folder>/<file>: content check failed
// (expected hash ..., got ...)"); empty when it is true.
std::string textureFileProblem(const std::filesystem::path& folder, const BakedTexture& texture);
// Sets the texture's mtimeNs and inode from its file now (one stat); false (and zeros) when the
// file cannot be read. Stamp before hashing: a write during the hash then shows next time.
bool stampTexture(const std::filesystem::path& folder, BakedTexture& texture);
// True when the texture has a recorded stamp, no depth file, and its file exists with the recorded size,
// last-write time and inode (one stat: the start-up check; see above for what it cannot see).
bool textureFileUnchanged(const std::filesystem::path& folder, const BakedTexture& texture);

}  // namespace cavewall::walls
