// `cavewall bake` end to end on a small generated plant (headless). The plan options keep the
// bake short: alpha 30°, zones of at least 5 m and textures of at most 64 texels give 64
// textures (`cavewall plan` prints the same count for these options).
#include "tests/support/run_cli.h"
#include "tests/support/gl/gl_test_support.h"
#include "walls/bake_manifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::string lastLine(const std::string& text) {
    std::string line, last;
    std::istringstream in(text);
    while (std::getline(in, line))
        if (!line.empty()) last = line;
    return last;
}

// Flips one byte of `file` in place, keeping its size, inode and last-write time: only its
// content tells.
void flipByteKeepingStamp(const std::filesystem::path& file) {
    const auto stamp = std::filesystem::last_write_time(file);
    {
        std::fstream f(file, std::ios::in | std::ios::out | std::ios::binary);
        f.seekg(-9, std::ios::end);
        const char c = static_cast<char>(f.get());
        f.seekp(-9, std::ios::end);
        f.put(static_cast<char>(c ^ 0x40));
    }
    std::filesystem::last_write_time(file, stamp);
}

void swapFiles(const std::filesystem::path& a, const std::filesystem::path& b) {
    const std::filesystem::path tmp = a.string() + ".swap";
    std::filesystem::rename(a, tmp);
    std::filesystem::rename(b, a);
    std::filesystem::rename(tmp, b);
}

// `out` emptied, a 20 k triangle plant generated into out/plant, and the arguments that bake it
// into out/cache at alpha 30° with zones of at least 5 m, `flags` added; empty (and the test
// failed) when the plant cannot be generated.
std::vector<std::string> plantBake(const std::filesystem::path& out, const std::vector<std::string>& flags) {
    std::filesystem::remove_all(out);
    const CliResult gen = runCavewall({"generate", "plant", "--triangles", "20000", "--out", (out / "plant").string()});
    if (gen.exitCode != 0) {
        ADD_FAILURE() << gen.err;
        return {};
    }
    std::vector<std::string> bake{
        "bake", (out / "plant").string(), "--cache", (out / "cache").string(), "--alpha", "30", "--min-zone", "5"};
    bake.insert(bake.end(), flags.begin(), flags.end());
    return bake;
}

class BakeCli : public testing::GlTest {};

TEST_F(BakeCli, BakesAGeneratedPlantAndReusesItsCache) {
    const std::filesystem::path out = testing::testOutputFolder("bake-cli");
    const std::vector<std::string> bake = plantBake(out, {"--max-res", "64", "--jobs", "2"});
    ASSERT_FALSE(bake.empty());
    const CliResult first = runCavewall(bake);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    // The last line is the bake folder, under the cache, holding a manifest of every texture.
    const std::filesystem::path folder = lastLine(first.out);
    EXPECT_EQ(folder.parent_path(), out / "cache");
    const walls::BakeManifest manifest = walls::readManifest(folder);
    // 64 textures of the cells' own walls and 436 of the far walls beyond a neighbour drawn as
    // geometry (`cavewall plan` of this scene at these options).
    EXPECT_EQ(manifest.textures.size(), 500u);
    EXPECT_EQ(manifest.alphaDeg, 30.0);
    // Depth walls by default, the kind `run` draws by default: each texture has its depth file.
    for (const walls::BakedTexture& t : manifest.textures) {
        EXPECT_TRUE(walls::textureFileValid(folder, t)) << t.file;
        EXPECT_FALSE(t.depthFile.empty()) << t.file;
    }
    EXPECT_THAT(first.out, HasSubstr("bake: 500 textures: 500 baked, 0 reused"));
    // stderr is not a terminal here: plain progress lines, the last one complete.
    EXPECT_THAT(first.err, HasSubstr("bake: 500/500 textures (500 baked, 0 reused)"));
    EXPECT_THAT(first.err, ::testing::Not(HasSubstr("\r")));

    const CliResult second = runCavewall(bake);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_THAT(second.out, HasSubstr("bake: 500 textures: 0 baked, 500 reused"));
    EXPECT_EQ(lastLine(second.out), folder.string());

    // A flipped byte in a cached texture (same size, time and inode) fails its content check:
    // re-baked, and named once. A temporary file a killed bake left an hour ago is removed; one
    // just written (a bake still writing) is kept.
    const std::filesystem::path flipped = folder / manifest.textures[7].file;
    flipByteKeepingStamp(flipped);
    const std::filesystem::path stale = folder / ".tex_0007_0000000000000000.tmp-999999-0.bct";
    const std::filesystem::path live = folder / ".tex_0008_0000000000000000.tmp-999999-1.bct";
    std::ofstream(stale) << "torn";
    std::ofstream(live) << "being written";
    std::filesystem::last_write_time(stale, std::filesystem::file_time_type::clock::now() - std::chrono::hours(1));
    const CliResult third = runCavewall(bake);
    ASSERT_EQ(third.exitCode, 0) << third.err;
    EXPECT_THAT(third.out, HasSubstr("bake: 500 textures: 1 baked, 499 reused"));
    EXPECT_THAT(third.err,
                HasSubstr("cavewall: warning: " + flipped.string() + ": content check failed (expected hash "));
    EXPECT_THAT(third.err, HasSubstr(") (re-baking it)"));
    EXPECT_THAT(third.err, HasSubstr(folder.string() + ": removed 1 temporary files an interrupted bake left behind"));
    EXPECT_FALSE(std::filesystem::exists(stale));
    EXPECT_TRUE(std::filesystem::exists(live));
    std::filesystem::remove(live);
    for (const walls::BakedTexture& t : walls::readManifest(folder).textures)
        EXPECT_TRUE(walls::textureFileValid(folder, t)) << t.file;

    // Two textures' files swapped on disk: both fail their checks and are re-baked.
    swapFiles(folder / manifest.textures[20].file, folder / manifest.textures[21].file);
    const CliResult fourth = runCavewall(bake);
    ASSERT_EQ(fourth.exitCode, 0) << fourth.err;
    EXPECT_THAT(fourth.out, HasSubstr("bake: 500 textures: 2 baked, 498 reused"));
    EXPECT_THAT(fourth.err, HasSubstr((folder / manifest.textures[20].file).string() + ": "));
    EXPECT_THAT(fourth.err, HasSubstr((folder / manifest.textures[21].file).string() + ": "));
}

// A scene with a zone size and texture side of its own ("planning") is baked with them: the
// same plan as --min-zone with that size, where the default (1 m) plans more textures, and
// textures no larger than its side.
TEST_F(BakeCli, PlansWithTheScenesOwnZoneSize) {
    const std::filesystem::path out = testing::testOutputFolder("bake-cli-zone");
    const std::vector<std::string> given = plantBake(out, {"--max-res", "16", "--limit", "1"});
    ASSERT_FALSE(given.empty());
    nlohmann::json plant;
    std::ifstream(out / "plant" / "scene.json") >> plant;
    plant["planning"] = {{"minZone", 5.0}, {"maxRes", 16}};
    std::ofstream(out / "plant" / "zoned.json") << plant.dump();
    // The plan's textures, from the first progress line ("bake: 0/N textures"; --limit 1 bakes one).
    auto textures = [](const CliResult& r) {
        EXPECT_EQ(r.exitCode, 0) << r.err;
        const std::size_t at = r.err.find("bake: 0/");
        return at == std::string::npos ? -1 : std::stoi(r.err.substr(at + 8));
    };
    const std::vector<std::string> common{"--cache", (out / "cache").string(), "--alpha", "30", "--limit", "1"};
    std::vector<std::string> own{"bake", (out / "plant" / "zoned.json").string()},
        bare{"bake", (out / "plant").string(), "--max-res", "16"};
    own.insert(own.end(), common.begin(), common.end());
    bare.insert(bare.end(), common.begin(), common.end());
    const int withFlag = textures(runCavewall(given));
    EXPECT_GT(withFlag, 0);
    const CliResult ownBake = runCavewall(own);
    EXPECT_EQ(textures(ownBake), withFlag);
    for (const walls::BakedTexture& t : walls::readManifest(lastLine(ownBake.out)).textures)
        EXPECT_LE(std::max(t.resolution.x, t.resolution.y), 16) << t.file;
    EXPECT_GT(textures(runCavewall(bare)), withFlag);
}

// The depth walls' manifest entries carry their own checks: an edited depth range, a deleted
// depth block (which would be drawn flat in a depth run) and an entry pointed at another
// texture's files are each refused on reading, named once, and re-baked; the intact entry is
// reused. A sample of four textures (--limit) keeps it short.
TEST_F(BakeCli, EditedDepthManifestEntriesAreRebaked) {
    const std::filesystem::path out = testing::testOutputFolder("bake-cli-depth");
    const std::vector<std::string> bake = plantBake(out, {"--max-res", "32", "--walls", "depth", "--limit", "4"});
    ASSERT_FALSE(bake.empty());
    const CliResult first = runCavewall(bake);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    const std::filesystem::path folder = lastLine(first.out);
    const std::filesystem::path file = folder / "manifest.json";
    nlohmann::json j = nlohmann::json::parse(std::ifstream(file));
    ASSERT_EQ(j["textures"].size(), 4u);
    for (const auto& t : j["textures"]) ASSERT_TRUE(t.contains("depth")) << t.dump();
    j["textures"][0]["depth"]["range"][1] = j["textures"][0]["depth"]["range"][1].get<double>() + 1.0;
    j["textures"][1].erase("depth");
    j["textures"][2]["file"] = j["textures"][3]["file"];
    j["textures"][2]["depth"]["file"] = j["textures"][3]["depth"]["file"];
    j["textures"][2]["texture"] = j["textures"][3]["texture"];
    std::ofstream(file) << j.dump(1);
    const CliResult second = runCavewall(bake);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_THAT(second.out, HasSubstr(" baked, 1 reused"));
    EXPECT_THAT(second.err,
                HasSubstr(file.string() + ": textures[0] (\"" + j["textures"][0]["file"].get<std::string>() +
                          "\"): depth: its check does not match its fields"));
    EXPECT_THAT(second.err,
                HasSubstr(file.string() + ": textures[1] (\"" + j["textures"][1]["file"].get<std::string>() +
                          "\"): its check does not match its fields"));
    EXPECT_THAT(second.err, HasSubstr(file.string() + ": textures[2] (\""));
    EXPECT_THAT(second.err,
                HasSubstr("but its file \"" + j["textures"][3]["file"].get<std::string>() + "\" is texture "));
}

TEST_F(BakeCli, BadArgumentsAreClearErrors) {
    const struct {
        const char* name;
        std::vector<std::string> args;
        const char* message;
    } cases[] = {
        {"no scene", {"bake"}, "SCENE"},
        {"jobs out of range", {"bake", "x", "--jobs", "0"}, "--jobs"},
        {"lod texels out of range", {"bake", "x", "--lod-texels", "5"}, "--lod-texels"},
        {"negative limit", {"bake", "x", "--limit", "-1"}, "--limit"},
        {"unknown flag", {"bake", "x", "--colour", "red"}, "--colour"},
        {"texture format",
         {"bake", "x", "--texture-format", "dxt9"},
         "--texture-format: expected one of rgba8, bc1, bc3, got 'dxt9'"},
        {"missing scene", {"bake", "/nonexistent/scene.json", "--cache", "/tmp"}, "/nonexistent/scene.json"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        const CliResult r = runCavewall(c.args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, StartsWith("cavewall: error: "));
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

}  // namespace
}  // namespace cavewall::test
