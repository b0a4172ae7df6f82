// The bake's settings check, its default cache folder and its texture file names (baker.h).
#include "walls/gl/baker.h"

#include "config/error.h"
#include "walls/bake_manifest.h"
#include "walls/texture_blocks.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace cavewall::walls::gl {

void validateBakeSettings(const BakeSettings& s) {
    auto fail = [](const char* name, const std::string& expected, const std::string& got) {
        throw Error(std::string("bake settings: ") + name + ": expected " + expected + ", got " + got);
    };
    if (s.maxResolution < 16 || s.maxResolution > 16384)
        fail("maxResolution", "[16, 16384]", std::to_string(s.maxResolution));
    if (s.tileSize < 16 || s.tileSize > 1024 || s.tileSize % 16 != 0)
        fail("tileSize", "a multiple of 16 in [16, 1024]", std::to_string(s.tileSize));
    if (s.jobs < 1 || s.jobs > 64) fail("jobs", "[1, 64]", std::to_string(s.jobs));
    if (s.drawThreads < 1 || s.drawThreads > 8) fail("drawThreads", "[1, 8]", std::to_string(s.drawThreads));
    if (!(s.ambient >= 0.0f && s.ambient <= 1.0f)) fail("ambient", "[0, 1]", std::to_string(s.ambient));
    if (!(s.lodTexels >= 0.0 && s.lodTexels <= 4.0)) fail("lodTexels", "[0, 4]", std::to_string(s.lodTexels));
}

std::filesystem::path defaultCacheFolder() {
    if (const char* cache = std::getenv("CAVEWALL_CACHE"); cache && *cache) return cache;
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "cavewall";
    throw Error("bake cache: expected $CAVEWALL_CACHE or $HOME to be set, got neither (use --cache DIR)");
}

std::string textureFileName(int id, std::uint64_t textureKey, walls::TextureFormat format) {
    char s[16];
    std::snprintf(s, sizeof s, "tex_%04d_", id);
    return s + walls::hex64(textureKey) + std::string(walls::textureFileExtension(format));
}

}  // namespace cavewall::walls::gl
