#pragma once
// The baked wall textures of a scene on disk: one folder per bake key holding manifest.json and
// one tiled, MIP-mapped image file per texture (written by walls/gl/baker.h).
//
// manifest.json:
//   {"version": 2, "key": "<16 hex digits>", "alphaDeg": 10,
//    "textures": [{"id": 0, "cell": 0, "wall": 0, "samplingPoint": [x, y, z],
//                  "resolution": [w, h], "file": "tex_0000.tx", "bytes": 123, "hash": "<16 hex>",
//                  "mtimeNs": 1796212345123456789, "inode": 1234,
//                  "depth": {"file": "tex_0000.depth.tif", "bytes": 45, "hash": "<16 hex>",
//                            "range": [near, far]}}]}
// ("depth" only for depth walls, walls/depth_file.h; the texture is valid when both files are.)
// `key` is a content hash of everything the textures depend on (scene files, plan, bake
// settings); `hash` is the FNV-1a 64 hash of the texture file's bytes. A texture is valid when
// its file exists with exactly `bytes` bytes and hash; anything else (missing, torn, replaced)
// is re-baked and never drawn. Manifests are written atomically (temporary file + rename), and
// after every texture file they list, so a manifest never names a file that was not complete.
//
// Two checks, cheap and exact: `mtimeNs` and `inode` are the file's last-write time (ns since
// the Unix epoch) and inode number when its bytes were last hashed. At start-up a bake trusts a
// file whose size, last-write time and inode still equal the manifest's (textureFileUnchanged:
// one stat, no read) and hashes only the others. The inode catches files renamed or swapped
// (which keep their times) and files replaced atomically; the time catches writes in place. The
// file system's clock is coarse (a few ms), so a same-size write in place within that tick of
// the stamp is not seen by the stat: the texture pager (walls/texture_pager.h) checks the hash
// before drawing, so such a file is still never drawn (it falls back). Version 1 manifests (no
// `mtimeNs`, `inode`) read with zeros: those files are hashed once, then stamped.

#include "config/error.h"

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
    std::uint64_t hash = 0;    // FNV-1a 64 of the file's bytes
    std::int64_t mtimeNs = 0;  // last-write time when the hash was checked; 0: unknown
    std::uint64_t inode = 0;   // inode number then
    // Depth walls only (walls/depth_file.h): the depth file beside `file`, its size and hash,
    // and the range of its finite depths (metres behind the wall). Empty for flat walls.
    std::string depthFile;
    std::uint64_t depthBytes = 0;
    std::uint64_t depthHash = 0;
    glm::dvec2 depthRange{0.0};
    bool operator==(const BakedTexture&) const = default;
};

struct BakeManifest {
    std::uint64_t key = 0;
    double alphaDeg = 0.0;
    std::vector<BakedTexture> textures;  // sorted by id
    bool operator==(const BakeManifest&) const = default;
};

// FNV-1a 64-bit hash, incremental: pass the previous result as `seed` to continue.
std::uint64_t fnv1a(std::string_view bytes, std::uint64_t seed = 0xcbf29ce484222325ull);
std::uint64_t hashFile(const std::filesystem::path& file);  // throws Error when unreadable
std::string hex64(std::uint64_t value);                     // 16 lower-case hex digits

std::string manifestToJson(const BakeManifest& manifest);
// Throws Error naming `source` and the JSON path on bad input.
BakeManifest manifestFromJson(std::string_view text, const std::string& source);

// Reads <folder>/manifest.json; nullopt-like empty manifest (key 0) when there is none.
BakeManifest readManifest(const std::filesystem::path& folder);
// Writes <folder>/manifest.json atomically.
void writeManifest(const std::filesystem::path& folder, const BakeManifest& manifest);
// Writes bytes to `file` atomically (scenes::writeAtomically).
void writeFileAtomically(const std::filesystem::path& file, std::string_view bytes);

// True when the texture's file (and its depth file, if any) exists with the recorded size and hash.
bool textureFileValid(const std::filesystem::path& folder, const BakedTexture& texture);
// Sets the texture's mtimeNs and inode from its file now (one stat); false (and zeros) when the
// file cannot be read. Stamp before hashing: a write during the hash then shows next time.
bool stampTexture(const std::filesystem::path& folder, BakedTexture& texture);
// True when the texture has a recorded stamp, no depth file, and its file exists with the recorded size,
// last-write time and inode (one stat: the start-up check; see above for what it cannot see).
bool textureFileUnchanged(const std::filesystem::path& folder, const BakedTexture& texture);

}  // namespace cavewall::walls
