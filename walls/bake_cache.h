#pragma once
// The bake cache folder beyond one bake key (walls/gl/baker.h): finding textures another folder
// already baked with the same texture key, taking them over, and removing files a manifest no
// longer lists. GL-free.

#include "walls/bake_manifest.h"

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

// Removes texture files (textureFileName pattern) in `folder` that `manifest` does not list.
// Returns how many were removed.
int removeUnlistedTextures(const std::filesystem::path& folder, const walls::BakeManifest& manifest);

}  // namespace cavewall::walls
