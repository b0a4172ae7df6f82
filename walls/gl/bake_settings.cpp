// The bake's settings check and key, its default cache folder and its texture file names
// (baker.h).
#include "walls/gl/baker.h"

#include "config/error.h"
#include "render/vertex_lighting.h"
#include "walls/bake_key.h"
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

std::uint64_t bakeSettingsKey(const BakeSettings& s) {
    KeyHasher h;
    // Bump the text when the renderer, the MIP filter or the file layout changes.
    h.text("cavewall bake settings v1");
    h.integer(s.maxResolution).integer(s.tileSize).number(s.ambient);
    // Flat bakes keep their keys (and caches); depth bakes get others (their files differ).
    // Depth files hold the march's halved depths (walls::marchDepths), not full ones.
    // Texels where only translucent surfaces were drawn have their depth (WallTextureRenderer).
    if (s.kind == walls::WallKind::Depth) h.text("depth wall v1").text("march depths v1").text("translucent depth v1");
    // The rendered colour is premultiplied already (walls::mipChainOfPremultiplied): translucent
    // texels are no longer multiplied by their alpha twice.
    h.text("premultiplied render v1");
    // Full-detail bakes keep their keys; levels of detail draw other pixels.
    if (s.lodTexels > 0.0) h.text("lod texels v1").number(s.lodTexels);
    // RGBA8 bakes keep their keys; block formats store other files (walls/texture_blocks.h).
    if (s.textureFormat != walls::TextureFormat::Rgba8)
        h.text("texture format v1").text(walls::textureFormatName(s.textureFormat));
    // BC1's opaque blocks come from stb_dxt, whose bytes differ from libsquish's blocks, and
    // textures with translucent texels are stored as Bc3 (walls::storedFormat).
    if (s.textureFormat == walls::TextureFormat::Bc1)
        h.text("bc1 opaque blocks stb_dxt v1").text("bc3 where translucent v1");
    // The wall renderer lights per vertex where that is within this tolerance (RenderSettings
    // default; render/vertex_lighting.h): other pixels, by at most half a level.
    h.text("vertex lighting v1").number(render::kVertexLightingTolerance);
    return h.value();
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
