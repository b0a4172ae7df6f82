// The windowed path (GLFW, one window per screen) shows the same pixels as the headless one.
// Run under a virtual X server: ctest runs this executable through `xvfb-run`.
#include "metrics/image_compare.h"
#include "scenes/image_io.h"
#include "tests/support/run_cli.h"
#include "tests/support/gl/gl_test_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

namespace cavewall::test {
namespace {

// Needs an X server: skipped without one, except under CI.
class Window : public ::testing::Test {
protected:
    void SetUp() override {
        const char* display = std::getenv("DISPLAY");
        if (display && *display) return;
        if (testing::onCi()) FAIL() << "CI=true: the windowed test needs an X server (run it through xvfb-run)";
        GTEST_SKIP() << "no $DISPLAY";
    }
};

TEST_F(Window, RenderWithWindowMatchesHeadless) {
    const std::filesystem::path out = testing::testOutputFolder("window");
    std::filesystem::remove_all(out);
    const std::vector<std::string> common{
        "render", "--display",      (testing::testConfigFolder() / "cave4_128.json").string(),
        "--eye",  "-0.6,1.45,-0.4", "--head-yaw",
        "20",     "--out"};
    auto run = [&](std::vector<std::string> args) {
        args.insert(args.begin(), common.begin(), common.end());
        const test::CliResult r = test::runCavewall(args);
        EXPECT_EQ(r.exitCode, 0) << r.err;
        return r.exitCode == 0;
    };
    ASSERT_TRUE(run({(out / "headless").string()}));
    ASSERT_TRUE(run({(out / "window").string(), "--window"}));
    // The windows have the screens' resolution, so the window images are the windows' back
    // buffers read before the swap (render/gl/snapshot.h): same pixels up to the blit.
    for (const char* stem : {"front", "left", "right", "floor", "foldout"}) {
        SCOPED_TRACE(stem);
        const std::string file = std::string(stem) + ".png";
        const metrics::ImageComparison r = metrics::compareImages(scenes::readImage(out / "window" / file),
                                                                  scenes::readImage(out / "headless" / file));
        EXPECT_TRUE(r.passes()) << r.describe();
    }
}

TEST_F(Window, QuadBufferWithoutStereoVisualsIsAClearError) {
    // Xvfb offers no stereo visuals, so the windows cannot be opened; the message says why.
    const test::CliResult r = test::runCavewall(
        {"render", "--display", (testing::testConfigFolder() / "cave4_128.json").string(), "--stereo", "quad-buffer",
         "--window", "--out", testing::testOutputFolder("window-quad-buffer").string()});
    EXPECT_EQ(r.exitCode, 1);
    EXPECT_THAT(r.err, ::testing::HasSubstr("cannot open a 128 x 128 quad-buffer stereo window"));
}

}  // namespace
}  // namespace cavewall::test
