// The texture store (walls/gl/texture_store.h) over a real pager: prefetches go up in bands over
// several frames and are drawn (resident) only once complete; a prefetch in flight that the
// frame comes to want now is finished in that frame; wanted-now textures go up whole at once.
#include "tests/support/gl/gl_test_support.h"
#include "walls/gl/texture_store.h"
#include "walls/bake_manifest.h"

#include <gtest/gtest.h>

#include <fstream>

namespace cavewall::walls::gl {
namespace {

class TextureStoreTest : public cavewall::testing::GlTest {
protected:
    // Four texture files (tiny placeholders: the decoder makes the texels) listed in a manifest.
    walls::BakeManifest files(const std::filesystem::path& dir) const {
        std::filesystem::create_directories(dir);
        walls::BakeManifest m;
        for (int i = 0; i < 4; ++i) {
            const std::string file = "tex_" + std::to_string(i);
            std::ofstream(dir / file) << "texture " << i;
            m.textures.push_back({i,
                                  0,
                                  0,
                                  {},
                                  {256, 256},
                                  file,
                                  std::filesystem::file_size(dir / file),
                                  walls::contentHashFile(dir / file).value()});
        }
        return m;
    }
    // Each file decodes to one 256 x 256 RGBA8 level: 256 KiB on the GPU.
    static walls::TextureLevels decode(const std::filesystem::path&) {
        scenes::Image level;
        level.width = level.height = 256;
        level.rgba.assign(256 * 256 * 4, 128);
        return walls::TextureLevels(std::vector<scenes::Image>{level});
    }
};

constexpr std::size_t kTexture = 256 * 256 * 4;

TEST_F(TextureStoreTest, PrefetchesGoUpInBandsAndAreDrawnOnlyWhenComplete) {
    const auto dir = cavewall::testing::testOutputFolder("texture_store") / "bands";
    walls::TexturePager pager(dir, files(dir), 64.0, decode);
    TextureStore store(pager, 8u << 20);
    pager.request({}, {0, 1, 2, 3});
    pager.waitIdle();
    // The pacer's first allowance is a share of the 1 MiB that arrived, far below one texture.
    std::size_t first = store.update();
    EXPECT_GT(first, 0u);
    EXPECT_LT(first, kTexture);
    EXPECT_FALSE(store.resident(0));
    int frames = 1;
    std::size_t total = first;
    while (!store.resident(0) && frames < 100) {
        pager.request({}, {0, 1, 2, 3});
        total += store.update();
        ++frames;
    }
    EXPECT_TRUE(store.resident(0));
    EXPECT_GT(frames, 2);
    EXPECT_GE(total, kTexture);
    EXPECT_EQ(glGetError(), GLenum(GL_NO_ERROR));

    // Texture 1 is in flight now (or next); wanting it now finishes it in this frame's update.
    pager.request({}, {1, 2, 3});
    store.update();
    ASSERT_FALSE(store.resident(1));
    pager.request({1}, {2, 3});
    store.update();
    EXPECT_TRUE(store.resident(1));
    EXPECT_FALSE(store.resident(3));
    // A texture wanted now that is merely ready goes up whole at once, beside the prefetch.
    pager.request({3}, {2});
    store.update();
    EXPECT_TRUE(store.resident(3));
    EXPECT_EQ(pager.stats().failures, 0);
}

}  // namespace
}  // namespace cavewall::walls::gl
