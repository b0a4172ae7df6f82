// `cavewall render` end to end (headless). (`cavewall demo` is tested in run_cli_test.cpp.)
#include "scenes/image_io.h"
#include "tests/support/run_cli.h"
#include "tests/support/gl/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>

#include <stdlib.h>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;

std::string testDisplay() { return (testing::testConfigFolder() / "cave4_128.json").string(); }

std::filesystem::path freshFolder(const std::string& name) {
    const std::filesystem::path out = testing::testOutputFolder(name);
    std::filesystem::remove_all(out);
    return out;
}

// The fixture probes for a headless context: without one these skip (or fail under CI) like
// every GL test, instead of failing on the command's error.
class RenderCli : public testing::GlTest {};

TEST_F(RenderCli, WritesOnePngPerScreenAndAFoldoutAndNamesTheRenderer) {
    const auto out = freshFolder("render-cli");
    const CliResult r =
        runCavewall({"render", "--display", testDisplay(), "--eye", "0.3,1.5,0.2", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    for (const char* stem : {"front", "left", "right", "floor", "foldout"}) {
        SCOPED_TRACE(stem);
        const std::string file = (out / (std::string(stem) + ".png")).string();
        EXPECT_THAT(r.out, HasSubstr("wrote " + file + "\n"));
        // Screens at their resolution; the fold-out is 3 x 2 screens of 128 pixels.
        const scenes::Image image = scenes::readImage(file);
        EXPECT_EQ(image.width, std::string(stem) == "foldout" ? 384 : 128);
    }
    EXPECT_THAT(r.out, HasSubstr("GL_RENDERER: "));
}

TEST_F(RenderCli, RendersAGltfFileWithViewAllAndPrintsTheFrameStatistics) {
    const auto out = freshFolder("render-cli-gltf");
    const std::string model =
        (std::filesystem::path(CAVEWALL_REAL_SCENES) / "BoxInterleaved/BoxInterleaved.glb").string();
    const CliResult r =
        runCavewall({"render", "--display", testDisplay(), "--scene", model, "--view-all", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The box is one object of 12 triangles; cave4 has 4 screens (mono), so 4 views. viewAll
    // frames it in the front screen only, so culling leaves it out of the other three.
    EXPECT_THAT(r.out, HasSubstr("1 objects, 12 triangles, 1 draw calls in 4 views; CPU "));
    EXPECT_THAT(r.out, HasSubstr(" ms), GPU "));
    const scenes::Image front = scenes::readImage((out / "front.png").string());
    const scenes::Image left = scenes::readImage((out / "left.png").string());
    auto distinct = [](const scenes::Image& image) {
        std::set<std::uint32_t> colours;
        for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
            colours.insert(image.rgba[i] << 16 | image.rgba[i + 1] << 8 | image.rgba[i + 2]);
        return colours.size();
    };
    EXPECT_GT(distinct(front), 2u);  // the box, shaded, over the background
    EXPECT_EQ(distinct(left), 1u);   // background only
}

TEST_F(RenderCli, ReducesTexturesToTheLimitsAndPrintsTheOutcome) {
    const auto out = freshFolder("render-cli-textures");
    const std::string model = (std::filesystem::path(CAVEWALL_REAL_SCENES) / "MultiUVTest/MultiUVTest.gltf").string();
    const CliResult r = runCavewall({"render", "--display", testDisplay(), "--scene", model, "--view-all",
                                     "--texture-max", "256", "--texture-budget", "1", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // Two 1024² images (8 MB of RGBA) reduced by 4 to 256² each: 0.5 MB, within 1 MB.
    EXPECT_THAT(r.out, HasSubstr("textures: 2 images, 8.0 MB decoded at full size -> 0.5 MB, largest side 256 px "
                                 "(limits: 256 px, budget 1.0 MB)\n"));
}

TEST_F(RenderCli, SeparateStereoWritesBothEyes) {
    const auto out = freshFolder("render-cli-separate");
    const CliResult r =
        runCavewall({"render", "--display", testDisplay(), "--stereo", "separate", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_TRUE(std::filesystem::exists(out / "front-left.png"));
    EXPECT_TRUE(std::filesystem::exists(out / "front-right.png"));
    EXPECT_TRUE(std::filesystem::exists(out / "foldout.png"));  // from the left eye
}

// cave4_128's front and left screens in `folder`, the front one corrected with `warp`.
std::string correctedDisplay(const std::filesystem::path& folder, const std::string& warp) {
    std::filesystem::create_directories(folder);
    std::ofstream(folder / "front.warp") << warp;
    std::ofstream(folder / "lab.json") << R"({"screens": [
        {"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, 3, -1.5],
         "resolution": [64, 64], "warp": "front.warp", "blackLevel": 0},
        {"name": "left", "lowerLeft": [-1.5, 0, 1.5], "lowerRight": [-1.5, 0, -1.5], "upperLeft": [-1.5, 3, 1.5],
         "resolution": [64, 64]}]})";
    return (folder / "lab.json").string();
}

TEST_F(RenderCli, CorrectedScreensWriteTheImageBeforeAndAfterTheWarp) {
    const auto out = freshFolder("render-cli-warp");
    const std::string identity = "cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 0\n0 1 0 1\n1 1 1 1\n";
    const CliResult r = runCavewall({"render", "--display", correctedDisplay(out, identity), "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("wrote " + (out / "front-warped.png").string()));
    // The identity warp leaves the image as it is; the left screen has no pass at all.
    EXPECT_EQ(scenes::readImage(out / "front-warped.png").rgba, scenes::readImage(out / "front.png").rgba);
    EXPECT_TRUE(std::filesystem::exists(out / "left.png"));
    EXPECT_FALSE(std::filesystem::exists(out / "left-warped.png"));
}

TEST_F(RenderCli, BadWarpFileNamesTheFileAndTheLine) {
    const auto out = freshFolder("render-cli-bad-warp");
    const std::string bad = "cavewall-warp 1\n2 2\n0 0 0 0\n1 0 1 0\n0 1 0 1\n1 1 1 nan\n";
    const CliResult r = runCavewall({"render", "--display", correctedDisplay(out, bad), "--out", out.string()});
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.err, HasSubstr((out / "front.warp").string() + ":6: node 3: y: expected a finite number, got 'nan'"));
}

// The model as the first word, as `view MODEL` takes it: the same frame as --scene MODEL, not
// the built-in room.
TEST_F(RenderCli, AModelAsTheFirstWordIsTheScene) {
    const std::string model =
        (std::filesystem::path(CAVEWALL_REAL_SCENES) / "BoxInterleaved/BoxInterleaved.glb").string();
    const auto word = freshFolder("render-cli-model-word");
    const auto flag = freshFolder("render-cli-model-flag");
    const CliResult a =
        runCavewall({"render", model, "--display", testDisplay(), "--view-all", "--out", word.string()});
    const CliResult b =
        runCavewall({"render", "--display", testDisplay(), "--scene", model, "--view-all", "--out", flag.string()});
    ASSERT_EQ(a.exitCode, 0) << a.err;
    ASSERT_EQ(b.exitCode, 0) << b.err;
    EXPECT_THAT(a.out, HasSubstr("1 objects, 12 triangles, 1 draw calls in 4 views; CPU "));
    EXPECT_EQ(scenes::readImage((word / "front.png").string()).rgba,
              scenes::readImage((flag / "front.png").string()).rgba);
}

TEST_F(RenderCli, BadInputGivesAClearErrorAndNonZeroExit) {
    const struct {
        const char* name;
        std::vector<std::string> args;
        const char* message;
    } cases[] = {
        {"missing scene file", {"--scene", "missing-lab.glb"}, "missing-lab.glb: cannot open the glTF file"},
        {"stereo",
         {"--stereo", "wobble"},
         "--stereo: expected one of mono, separate, side-by-side, top-bottom, anaglyph, quad-buffer, got 'wobble'"},
        {"quad-buffer headless",
         {"--stereo", "quad-buffer"},
         "stereo mode quad-buffer needs windows with quad-buffer stereo"},
        {"no output folder", {}, "--out: required flag is missing"},
        {"texture side", {"--texture-max", "0"}, "--texture-max: expected an integer in [1, 16384], got '0'"},
        {"texture budget",
         {"--texture-budget", "-5"},
         "--texture-budget: expected an integer in [1, 1048576], got '-5'"},
        {"model and --scene",
         {"room.glb", "--scene", "hall.glb"},
         "render: expected the scene once, as MODEL or --scene, got both ('room.glb' and 'hall.glb')"},
        {"two models", {"room.glb", "hall.glb"}, "render: unexpected word 'hall.glb' (expected at most one MODEL"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        std::vector<std::string> args{"render", "--display", testDisplay()};
        args.insert(args.end(), c.args.begin(), c.args.end());
        if (std::string(c.name) != "no output folder")
            args.insert(args.end(), {"--out", freshFolder("render-cli-bad").string()});
        const CliResult r = runCavewall(args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

TEST_F(RenderCli, WindowWithoutAWindowSystemIsAClearError) {
    // The child inherits this process' environment: take the window system away.
    ::unsetenv("DISPLAY");
    ::unsetenv("WAYLAND_DISPLAY");
    const CliResult r = runCavewall(
        {"render", "--display", testDisplay(), "--window", "--out", freshFolder("render-cli-window").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, HasSubstr("--window: cannot open windows: "));
    EXPECT_THAT(r.err, HasSubstr("leave out --window to render headless"));
}

}  // namespace
}  // namespace cavewall::test
