// `cavewall display`: the summary, the picture, and the refusals with their messages.
#include "tests/support/run_cli.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <utility>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;

const std::string kCave4 = CAVEWALL_SOURCE_DIR "/config/cave4.json";

// Width and height from a PNG's IHDR chunk (big-endian, bytes 16 to 23).
std::pair<std::uint32_t, std::uint32_t> pngSize(const std::filesystem::path& file) {
    const std::string bytes = readFile(file);
    if (bytes.size() < 24 || bytes.compare(1, 3, "PNG") != 0) return {0, 0};
    const auto word = [&](std::size_t at) {
        std::uint32_t v = 0;
        for (std::size_t i = 0; i < 4; ++i) v = v << 8 | static_cast<unsigned char>(bytes[at + i]);
        return v;
    };
    return {word(16), word(20)};
}

TEST(DisplayCli, PrintsEveryScreenAndTheModes) {
    const CliResult r = runCavewall({"display", kCave4});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* name : {"front", "left", "right", "floor"})
        EXPECT_THAT(r.out, HasSubstr("\n  " + std::string(name)));
    EXPECT_THAT(r.out, HasSubstr("4 screens, stereo separate, near 0.05 m, far infinite"));
    EXPECT_THAT(r.out, HasSubstr("default head [0, 1.7, 0] m"));
    EXPECT_THAT(r.out, HasSubstr("shared edge: front and left"));
}

TEST(DisplayCli, PngHasTheStatedSize) {
    const TempFolder folder("display_cli_png");
    const std::filesystem::path png = folder / "cave4.png";
    const CliResult r = runCavewall({"display", kCave4, "--png", png.string(), "--size", "900x500"});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("wrote " + png.string()));
    EXPECT_EQ(pngSize(png), (std::pair<std::uint32_t, std::uint32_t>{900, 500}));
}

TEST(DisplayCli, BadConfigsGiveTheReadersErrorAndNonZeroExit) {
    const TempFolder folder("display_cli_bad");
    writeFile(folder / "lab.json",
              R"({"screens": [{"name": "front", "lowerLeft": [0, 0, -1], "lowerRight": [1, 0, -1],
                  "upperLeft": [2, 0, -1], "resolution": [64, 64]}]})");
    CliResult r = runCavewall({"display", (folder / "lab.json").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("lab.json: screens[0]"));
    EXPECT_THAT(r.err, HasSubstr("collinear"));
    r = runCavewall({"display", (folder / "missing.json").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("missing.json"));
    r = runCavewall({"display"});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.err, HasSubstr("CONFIG"));
}

// The warp and blend files are read as a run reads them: sizes printed, a bad file refused
// before the run, naming the screen and the file.
TEST(DisplayCli, ReadsEachScreensWarpAndBlendFiles) {
    const TempFolder folder("display_cli_correction");
    const std::string screen = R"({"screens": [{"name": "front", "lowerLeft": [-1, 0, -1], "lowerRight": [1, 0, -1],
                                      "upperLeft": [-1, 2, -1], "resolution": [64, 64], )";
    writeFile(folder / "good.warp",
              "cavewall-warp 1\n3 2\n0 0 0 0\n0.5 0 0.5 0\n1 0 1 0\n0 1 0 1\n0.5 1 0.5 1\n-1 -1 1 1\n");
    writeFile(folder / "good.json", screen + R"("warp": "good.warp"}]})");
    CliResult r = runCavewall({"display", (folder / "good.json").string()});
    EXPECT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("screen front correction: warp 3 x 2 nodes (1 outside the projection)"));
    writeFile(folder / "short.warp", "cavewall-warp 1\n3 3\n0 0 0 0\n");
    writeFile(folder / "short.json", screen + R"("warp": "short.warp"}]})");
    r = runCavewall({"display", (folder / "short.json").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("short.json: screens[0] 'front': "));
    EXPECT_THAT(r.err, HasSubstr("short.warp: expected 9 node lines (3 x 3), got 1"));
    writeFile(folder / "mask.png", "\x89PNG\r\n\x1a\n truncated");
    writeFile(folder / "blend.json", screen + R"("blend": "mask.png"}]})");
    r = runCavewall({"display", (folder / "blend.json").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("blend.json: screens[0] 'front': "));
    EXPECT_THAT(r.err, HasSubstr("mask.png: PNG chunk at byte 8: expected 12 bytes of length, type and CRC, got 10 "
                                 "(the file is truncated)"));
}

TEST(DisplayCli, RefusesToWriteOverItsInputOrAFolder) {
    const TempFolder folder("display_cli_refuse");
    const std::filesystem::path copy = folder / "cave4.json";
    std::filesystem::copy_file(kCave4, copy);
    CliResult r = runCavewall({"display", copy.string(), "--png", copy.string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("expected a file apart from the command's inputs"));
    EXPECT_EQ(readFile(copy), readFile(kCave4));  // the input is untouched
    r = runCavewall({"display", kCave4, "--png", folder.path().string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("--png " + folder.path().string() + ": expected a regular file or a new name"));
}

}  // namespace
}  // namespace cavewall::test
