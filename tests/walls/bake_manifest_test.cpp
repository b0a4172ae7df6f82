#include "walls/bake_manifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <fstream>
#include <unistd.h>

namespace cavewall::walls {
namespace {

using ::testing::HasSubstr;

std::filesystem::path scratch(const char* name) {
    const auto dir = std::filesystem::temp_directory_path() / ("cavewall_manifest_" + std::string(name));
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir);
    return dir;
}

TEST(BakeManifest, Fnv1aMatchesPublishedVectors) {
    // Reference values of the FNV-1a 64 specification (Fowler/Noll/Vo test suite).
    EXPECT_EQ(fnv1a(""), 0xcbf29ce484222325ull);
    EXPECT_EQ(fnv1a("a"), 0xaf63dc4c8601ec8cull);
    EXPECT_EQ(fnv1a("foobar"), 0x85944171f73967e8ull);
    // Incremental hashing equals one-shot hashing.
    EXPECT_EQ(fnv1a("bar", fnv1a("foo")), fnv1a("foobar"));
}

TEST(BakeManifest, RoundTripsThroughDisk) {
    const auto dir = scratch("roundtrip");
    BakeManifest m{0x0123456789abcdefull, 10.0, {{3, 1, 2, {0.5, 1.6, -2.25}, {512, 256}, "tex_0003.tx", 42, 0xfeedull}}};
    writeManifest(dir, m);
    EXPECT_EQ(readManifest(dir), m);
    // Nothing but the manifest is left behind: the temporary file was renamed.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

TEST(BakeManifest, MissingManifestIsEmpty) { EXPECT_EQ(readManifest(scratch("none")).key, 0u); }

TEST(BakeManifest, TornOrReplacedTextureFilesAreDetected) {
    const auto dir = scratch("torn");
    writeFileAtomically(dir / "tex.tx", "0123456789");
    BakedTexture t{0, 0, 0, {}, {1, 1}, "tex.tx", 10, hashFile(dir / "tex.tx")};
    EXPECT_TRUE(textureFileValid(dir, t));
    std::filesystem::resize_file(dir / "tex.tx", 5);  // torn
    EXPECT_FALSE(textureFileValid(dir, t));
    writeFileAtomically(dir / "tex.tx", "0123456780");  // same size, other bytes
    EXPECT_FALSE(textureFileValid(dir, t));
    std::filesystem::remove(dir / "tex.tx");
    EXPECT_FALSE(textureFileValid(dir, t));
}

TEST(BakeManifest, BadManifestsNameThePath) {
    const struct {
        const char* json;
        const char* message;
    } cases[] = {
        {R"({"version": 2, "key": "0000000000000000", "alphaDeg": 10, "textures": []})", "m.json: version: expected an integer in [1, 1], got 2"},
        {R"({"version": 1, "key": "xyz", "alphaDeg": 10, "textures": []})", "m.json: key: expected 16 lower-case hex digits"},
        {R"({"version": 1, "key": "0000000000000000", "alphaDeg": 10, "textures": [{"id": 0, "cell": 0, "wall": 0,
            "samplingPoint": [0,0,0], "resolution": [4,4], "file": "../etc/passwd", "bytes": 1, "hash": "0000000000000000"}]})",
         "m.json: textures[0].file: expected a plain file name"},
        {"{", "m.json: not valid JSON"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.message);
        EXPECT_THAT([&] { manifestFromJson(c.json, "m.json"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
}  // namespace cavewall::walls
