// `cavewall bake` end to end on a small generated plant (headless). The plan options keep the
// bake short: alpha 30°, zones of at least 5 m and textures of at most 64 texels give 64
// textures (`cavewall plan` prints the same count for these options).
#include "tests/cli/run_cli.h"
#include "tests/gl/gl_test_support.h"
#include "walls/bake_manifest.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <sstream>

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

class BakeCli : public testing::GlTest {};

TEST_F(BakeCli, BakesAGeneratedPlantAndReusesItsCache) {
    const std::filesystem::path out = testing::testOutputFolder("bake-cli");
    std::filesystem::remove_all(out);
    const CliResult gen = runCavewall({"generate", "plant", "--triangles", "20000", "--out", (out / "plant").string()});
    ASSERT_EQ(gen.exitCode, 0) << gen.err;
    const std::vector<std::string> bake{"bake",       (out / "plant").string(),
                                        "--cache",    (out / "cache").string(),
                                        "--alpha",    "30",
                                        "--min-zone", "5",
                                        "--max-res",  "64",
                                        "--jobs",     "2"};
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
    for (const walls::BakedTexture& t : manifest.textures) EXPECT_TRUE(walls::textureFileValid(folder, t)) << t.file;
    EXPECT_THAT(first.out, HasSubstr("bake: 500 textures: 500 baked, 0 reused"));
    // stderr is not a terminal here: plain progress lines, the last one complete.
    EXPECT_THAT(first.err, HasSubstr("bake: 500/500 textures (500 baked, 0 reused)"));
    EXPECT_THAT(first.err, ::testing::Not(HasSubstr("\r")));

    const CliResult second = runCavewall(bake);
    ASSERT_EQ(second.exitCode, 0) << second.err;
    EXPECT_THAT(second.out, HasSubstr("bake: 500 textures: 0 baked, 500 reused"));
    EXPECT_EQ(lastLine(second.out), folder.string());
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
