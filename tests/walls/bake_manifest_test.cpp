#include "walls/bake_manifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

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
    BakedTexture t{0, 0, 0, {}, {1, 1}, "tex.tx", 10, contentHashFile(dir / "tex.tx").value()};
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
    BakedTexture t{0, 0, 0, {}, {1, 1}, "tex.tx", 10, contentHashFile(dir / "tex.tx").value()};
    EXPECT_TRUE(textureFileValid(dir, t));
    std::filesystem::resize_file(dir / "tex.tx", 5);  // torn
    EXPECT_FALSE(textureFileValid(dir, t));
    writeFileAtomically(dir / "tex.tx", "0123456780");  // same size, other bytes
    EXPECT_FALSE(textureFileValid(dir, t));
    std::filesystem::remove(dir / "tex.tx");
    EXPECT_FALSE(textureFileValid(dir, t));
}

// A depth wall's entry as a bake writes it: the texture key in its file names.
BakedTexture depthEntry() {
    BakedTexture t{3, 1, 2, {0.5, 1.6, -2.25}, {512, 256}, "tex_0003_00000000000000aa.bct", 42, 0xfeedull};
    t.depthFile = "tex_0003_00000000000000aa.depth.tif";
    t.depthBytes = 99;
    t.depthHash = 0xbeefull;
    t.depthRange = {0.25, 18.5};
    return t;
}

TEST(BakeManifest, EntriesCarryTheirTextureAndChecks) {
    const BakeManifest m{1, 10.0, {depthEntry()}};
    const nlohmann::json j = nlohmann::json::parse(manifestToJson(m));
    EXPECT_EQ(j["version"], 3);
    EXPECT_EQ(j["textures"][0]["texture"], "00000000000000aa");
    EXPECT_EQ(j["textures"][0]["check"], hex64(entryCheck(depthEntry())));
    EXPECT_EQ(j["textures"][0]["depth"]["check"], hex64(depthCheck(depthEntry())));
    EXPECT_EQ(manifestFromJson(j.dump(), "m.json"), m);
}

// Each edit of a written entry drops that entry (re-baked, never drawn) with a message naming
// the manifest, the entry and its file; the other entries are kept.
TEST(BakeManifest, EditedEntriesAreRejected) {
    BakedTexture other = depthEntry();
    other.id = 4;
    other.file = "tex_0004_00000000000000bb.bct";
    other.depthFile = "tex_0004_00000000000000bb.depth.tif";
    const std::string written = manifestToJson(BakeManifest{1, 10.0, {depthEntry(), other}});
    const struct {
        const char* name;
        void (*edit)(nlohmann::json& entry);
        const char* message;
    } cases[] = {
        {"depth range edited", [](nlohmann::json& e) { e["depth"]["range"][1] = 30.0; },
         "depth: its check does not match its fields"},
        {"depth block deleted (would be drawn flat)", [](nlohmann::json& e) { e.erase("depth"); },
         "its check does not match its fields"},
        {"depth check deleted", [](nlohmann::json& e) { e["depth"].erase("check"); }, "got (none)"},
        {"pointed at another texture's files",
         [](nlohmann::json& e) {
             e["file"] = "tex_0004_00000000000000bb.bct";
             e["texture"] = "00000000000000bb";
         },
         "names texture 3 but its file \"tex_0004_00000000000000bb.bct\" is texture 4's"},
        {"pointed at the same texture's file of another key",
         [](nlohmann::json& e) { e["file"] = "tex_0003_00000000000000cc.bct"; },
         "is for texture key 00000000000000aa but its file \"tex_0003_00000000000000cc.bct\" has key "
         "00000000000000cc"},
        {"depth file pointed at another texture's",
         [](nlohmann::json& e) { e["depth"]["file"] = "tex_0004_00000000000000bb.depth.tif"; },
         "depth: its check does not match its fields"},
        {"size edited", [](nlohmann::json& e) { e["bytes"] = 43; }, "its check does not match its fields"},
        {"hash edited", [](nlohmann::json& e) { e["hash"] = "000000000000feee"; }, "its check does not match"},
        {"sampling point edited", [](nlohmann::json& e) { e["samplingPoint"][0] = 0.75; }, "its check does not"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        nlohmann::json j = nlohmann::json::parse(written);
        c.edit(j["textures"][0]);
        const BakeManifest m = manifestFromJson(j.dump(), "m.json");
        ASSERT_EQ(m.textures.size(), 1u);
        EXPECT_EQ(m.textures[0].id, 4);
        ASSERT_EQ(m.rejected.size(), 1u);
        EXPECT_THAT(m.rejected[0], HasSubstr("m.json: textures[0] (\""));
        EXPECT_THAT(m.rejected[0], HasSubstr(c.message));
    }
}

TEST(BakeManifest, OlderVersionsReadAsStale) {
    const BakeManifest m = manifestFromJson(R"({"version": 2, "key": "0000000000000001", "alphaDeg": 10, "textures": [
        {"id": 0, "cell": 0, "wall": 0, "samplingPoint": [0,0,0], "resolution": [4,4], "file": "t.tx", "bytes": 1,
         "hash": "00000000000000ff", "mtimeNs": 5, "inode": 6}]})",
                                            "m.json");
    EXPECT_EQ(m.version, 2);  // < kManifestVersion: the baker re-bakes every texture it lists
    EXPECT_EQ(m.textures.size(), 1u);
    EXPECT_TRUE(m.rejected.empty());
}

TEST(BakeManifest, ProblemsNameTheFileAndTheHashes) {
    const auto dir = scratch("problem");
    writeFileAtomically(dir / "tex.bct", "0123456789");
    BakedTexture t{0, 0, 0, {}, {1, 1}, "tex.bct", 10, contentHash("0123456789")};
    EXPECT_EQ(textureFileProblem(dir, t), "");
    writeFileAtomically(dir / "tex.bct", "0123456788");
    EXPECT_EQ(textureFileProblem(dir, t), (dir / "tex.bct").string() + ": content check failed (expected hash " +
                                              hex64(contentHash("0123456789")) + ", got " +
                                              hex64(contentHash("0123456788")) + ")");
    writeFileAtomically(dir / "tex.bct", "01234");
    EXPECT_EQ(textureFileProblem(dir, t), (dir / "tex.bct").string() + ": expected 10 bytes, got 5");
}

TEST(BakeManifest, BadManifestsNameThePath) {
    const struct {
        const char* json;
        const char* message;
    } cases[] = {
        {R"({"version": 4, "key": "0000000000000000", "alphaDeg": 10, "textures": []})",
         "m.json: version: expected an integer in [1, 3], got 4"},
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
