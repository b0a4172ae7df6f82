// Depth files and the manifest's depth entries (walls/depth_file.h, bake_manifest.h): depths
// round-trip bit for bit (inf included), a depth texture is valid only when both its files are,
// and bad depth entries are rejected naming the JSON path.
#include "walls/bake_manifest.h"
#include "walls/depth_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;

std::filesystem::path scratch(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / ("cavewall_depth_file_" + std::string(name));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(DepthFile, NamesFollowTheColourFile) {
    EXPECT_EQ(depthFileName("tex_0003_0123456789abcdef.tx"), "tex_0003_0123456789abcdef.depth.tif");
    EXPECT_EQ(depthFileName("tex_0003_0123456789abcdef.bct"), "tex_0003_0123456789abcdef.depth.tif");
}

TEST(DepthFile, DepthsRoundTripBitForBit) {
    const auto dir = scratch("roundtrip");
    DepthImage image{7, 5, {}};
    for (int i = 0; i < 35; ++i) image.depth.push_back(i % 6 == 0 ? kNoSurface : 0.001f * i * i + 1.0f / 3.0f);
    writeDepthFile(dir / "d.depth.tif", image);
    const DepthImage back = readDepthFile(dir / "d.depth.tif");
    ASSERT_EQ(back.width, 7);
    ASSERT_EQ(back.height, 5);
    ASSERT_EQ(back.depth.size(), image.depth.size());
    EXPECT_EQ(std::memcmp(back.depth.data(), image.depth.data(), image.depth.size() * sizeof(float)), 0);
    EXPECT_EQ(depthRange(back), glm::dvec2(image.depth[1], image.depth[34]));
    EXPECT_THROW(writeDepthFile(dir / "bad.depth.tif", DepthImage{3, 3, {1.0f}}), Error);
    EXPECT_THROW(readDepthFile(dir / "missing.depth.tif"), Error);
}

TEST(DepthFile, ATextureIsValidOnlyWithItsDepthFile) {
    const auto dir = scratch("valid");
    std::ofstream(dir / "tex_0000_0000000000000001.tx") << "colour";
    writeDepthFile(dir / "tex_0000_0000000000000001.depth.tif", DepthImage{2, 1, {1.0f, 2.0f}});
    BakedTexture t;
    t.file = "tex_0000_0000000000000001.tx";
    t.bytes = 6;
    t.hash = hashFile(dir / t.file);
    EXPECT_TRUE(textureFileValid(dir, t));  // a flat texture: no depth file needed
    t.depthFile = depthFileName(t.file);
    t.depthBytes = std::filesystem::file_size(dir / t.depthFile);
    t.depthHash = hashFile(dir / t.depthFile);
    EXPECT_TRUE(textureFileValid(dir, t));
    writeDepthFile(dir / t.depthFile, DepthImage{2, 1, {1.0f, 2.5f}});  // replaced: same size, other hash
    EXPECT_FALSE(textureFileValid(dir, t));
    std::filesystem::remove(dir / t.depthFile);
    EXPECT_FALSE(textureFileValid(dir, t));
}

TEST(DepthFile, ManifestKeepsDepthEntriesAndRejectsBadOnes) {
    BakeManifest m{0x0123456789abcdefull, 10.0, {}};
    BakedTexture t{3, 1, 2, {0.5, 1.6, -2.25}, {512, 256}, "tex_0003.tx", 42, 0xfeedull};
    t.depthFile = "tex_0003.depth.tif", t.depthBytes = 99, t.depthHash = 0xbeefull, t.depthRange = {0.25, 18.5};
    m.textures.push_back(t);
    EXPECT_EQ(manifestFromJson(manifestToJson(m), "m.json"), m);
    std::string text = manifestToJson(m);
    text.replace(text.find("tex_0003.depth.tif"), 18, "../escape.depth.ti");
    try {
        manifestFromJson(text, "m.json");
        FAIL();
    } catch (const Error& e) {
        EXPECT_THAT(e.what(), HasSubstr("depth"));
        EXPECT_THAT(e.what(), HasSubstr("plain file name"));
    }
}

}  // namespace
}  // namespace cavewall::walls
