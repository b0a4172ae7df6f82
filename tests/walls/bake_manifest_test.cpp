#include "walls/bake_manifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
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
    // A time in nanoseconds needs all 64 bits (a double would round it to 256 ns).
    BakeManifest m{0x0123456789abcdefull,
                   10.0,
                   {{3,
                     1,
                     2,
                     {0.5, 1.6, -2.25},
                     {512, 256},
                     "tex_0003.tx",
                     42,
                     0xfeedull,
                     1796212345123456789,
                     9007199254740993}}};
    writeManifest(dir, m);
    EXPECT_EQ(readManifest(dir), m);
    // Nothing but the manifest is left behind: the temporary file was renamed.
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), std::filesystem::directory_iterator()), 1);
}

TEST(BakeManifest, Version1ManifestsReadWithoutStamps) {
    const BakeManifest m = manifestFromJson(R"({"version": 1, "key": "0000000000000001", "alphaDeg": 10, "textures": [
        {"id": 0, "cell": 0, "wall": 0, "samplingPoint": [0,0,0], "resolution": [4,4], "file": "t.tx", "bytes": 1,
         "hash": "00000000000000ff"}]})",
                                            "m.json");
    ASSERT_EQ(m.textures.size(), 1u);
    EXPECT_EQ(m.textures[0].hash, 0xffu);
    EXPECT_EQ(m.textures[0].mtimeNs, 0);  // unknown: the start-up check hashes it once
    EXPECT_EQ(m.textures[0].inode, 0u);
    EXPECT_FALSE(textureFileUnchanged(".", m.textures[0]));
}

// The start-up check (one stat) sees a file resized, rewritten later, replaced or renamed over;
// it cannot see a same-size write in place that leaves the time as it was (a write within the
// file system's clock tick of the stamp, here forced by setting the time back): the hash can.
TEST(BakeManifest, StatCheckSeesChangesExceptASameSizeWriteAtTheSameTime) {
    const auto dir = scratch("stamp");
    writeFileAtomically(dir / "tex.tx", "0123456789");
    writeFileAtomically(dir / "other.tx", "abcdefghij");
    BakedTexture t{0, 0, 0, {}, {1, 1}, "tex.tx", 10, hashFile(dir / "tex.tx")};
    EXPECT_FALSE(textureFileUnchanged(dir, t));  // never stamped
    ASSERT_TRUE(stampTexture(dir, t));
    EXPECT_NE(t.mtimeNs, 0);
    EXPECT_NE(t.inode, 0u);
    EXPECT_TRUE(textureFileUnchanged(dir, t));
    const auto stamped = std::filesystem::last_write_time(dir / "tex.tx");

    std::filesystem::last_write_time(dir / "tex.tx", stamped + std::chrono::seconds(1));  // touched
    EXPECT_FALSE(textureFileUnchanged(dir, t));
    EXPECT_TRUE(textureFileValid(dir, t));  // the bytes are the same: hashing keeps it

    std::filesystem::last_write_time(dir / "tex.tx", stamped);
    ASSERT_TRUE(textureFileUnchanged(dir, t));
    {
        std::fstream f(dir / "tex.tx", std::ios::in | std::ios::out | std::ios::binary);
        f.seekp(3);
        f.put('x');
    }
    std::filesystem::last_write_time(dir / "tex.tx", stamped);
    EXPECT_TRUE(textureFileUnchanged(dir, t));  // what the stat cannot see...
    EXPECT_FALSE(textureFileValid(dir, t));     // ...the hash does

    // Replaced by another file of the same size and time: a new inode.
    writeFileAtomically(dir / "tex.tx", "0123456789");
    std::filesystem::last_write_time(dir / "tex.tx", stamped);
    EXPECT_FALSE(textureFileUnchanged(dir, t));
    // Renamed over by a file with the same size and time: its own inode.
    std::filesystem::last_write_time(dir / "other.tx", stamped);
    std::filesystem::rename(dir / "other.tx", dir / "tex.tx");
    EXPECT_FALSE(textureFileUnchanged(dir, t));
    std::filesystem::resize_file(dir / "tex.tx", 5);
    EXPECT_FALSE(textureFileUnchanged(dir, t));
    std::filesystem::remove(dir / "tex.tx");
    EXPECT_FALSE(textureFileUnchanged(dir, t));
    EXPECT_FALSE(stampTexture(dir, t));
    EXPECT_EQ(t.mtimeNs, 0);
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
        {R"({"version": 3, "key": "0000000000000000", "alphaDeg": 10, "textures": []})",
         "m.json: version: expected an integer in [1, 2], got 3"},
        {R"({"version": 1, "key": "xyz", "alphaDeg": 10, "textures": []})",
         "m.json: key: expected 16 lower-case hex digits"},
        {R"({"version": 1, "key": "0000000000000000", "alphaDeg": 10, "textures": [{"id": 0, "cell": 0, "wall": 0,
            "samplingPoint": [0,0,0], "resolution": [4,4], "file": "../etc/passwd", "bytes": 1, "hash": "0000000000000000"}]})",
         "m.json: textures[0].file: expected a plain file name"},
        {R"({"version": 2, "key": "0000000000000000", "alphaDeg": 10, "textures": [{"id": 0, "cell": 0, "wall": 0,
            "samplingPoint": [0,0,0], "resolution": [4,4], "file": "t.tx", "bytes": 1, "hash": "0000000000000000",
            "mtimeNs": 1.5e18, "inode": 3}]})",
         "m.json: textures[0].mtimeNs: expected an integer in [0, 2^63), got"},
        {R"({"version": 2, "key": "0000000000000000", "alphaDeg": 10, "textures": [{"id": 0, "cell": 0, "wall": 0,
            "samplingPoint": [0,0,0], "resolution": [4,4], "file": "t.tx", "bytes": 1, "hash": "0000000000000000",
            "mtimeNs": 1}]})",
         "m.json: textures[0]: missing required key 'inode'"},
        {"{", "m.json: not valid JSON"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.message);
        EXPECT_THAT([&] { manifestFromJson(c.json, "m.json"); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

}  // namespace
}  // namespace cavewall::walls
