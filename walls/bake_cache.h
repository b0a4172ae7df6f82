#pragma once
// The bake cache folder beyond one bake key (walls/gl/baker.h): finding textures another folder
// already baked with the same texture key, taking them over, and removing files a manifest no
// longer lists. GL-free.

#include "walls/bake_manifest.h"

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>

namespace cavewall::walls {

struct CachedTexture {
    std::filesystem::path folder;
    walls::BakedTexture entry;
};

// Texture key -> a texture listed in another folder's manifest.
using CacheIndex = std::map<std::uint64_t, CachedTexture>;

// The texture key in a file name made by textureFileName, or nullopt for other names.
std::optional<std::uint64_t> textureKeyOf(const std::string& fileName);

// Reads the manifests of every folder in `cache` except `skip`; unreadable manifests are
// ignored (they only make the cache less useful).
CacheIndex indexCache(const std::filesystem::path& cache, const std::filesystem::path& skip);

// When `index` holds a texture with the key in `wanted.file` whose file is valid, links it (hard
// link, else copy) atomically into `folder` under `wanted.file`, checks it again and returns
// `wanted` with its bytes and hash; nullopt otherwise.
std::optional<walls::BakedTexture> linkCachedTexture(const CacheIndex& index, const std::filesystem::path& folder,
                                                     const walls::BakedTexture& wanted);

// A temporary file older than this was left by a bake that died (a live writer's file is
// written to at least this often): removeStaleTemporaries may delete it.
inline constexpr std::chrono::minutes kStaleTemporaryAge{10};

// True for the names of temporary files this code writes in a bake folder: ".<stem>.tmp-<pid>-<n><ext>"
// (scenes::writeAtomically) and ".<name>.link-<pid>" (linkCachedTexture).
bool isBakeTemporary(const std::string& fileName);

// Removes the regular files in `folder` whose names isBakeTemporary accepts and whose
// last-write time is at least `age` ago (only those: another process's bake still writing keeps
// its files); returns how many. A folder that does not exist holds none.
int removeStaleTemporaries(const std::filesystem::path& folder, std::chrono::seconds age);

// Removes texture files (textureFileName pattern) in `folder` that `manifest` does not list.
// Returns how many were removed.
int removeUnlistedTextures(const std::filesystem::path& folder, const walls::BakeManifest& manifest);

}  // namespace cavewall::walls
