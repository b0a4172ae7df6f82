// `cavewall view` and the session flags it brought to `run`, headless: the start inside the
// model, --resolution, --version and the errors. The window itself: view_window_cli_test.cpp.
#include "tests/tools/run_cli_support.h"
#include "tests/support/csv_table.h"

#include "scenes/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;
using ::testing::StartsWith;

const std::string kRoom = std::string(CAVEWALL_REAL_SCENES) + "/OcclusionRoom/room.glb";

TEST(ViewCli, VersionAndHelpListViewFirst) {
    const CliResult version = runCavewall({"--version"});
    EXPECT_EQ(version.exitCode, 0);
    EXPECT_EQ(version.out, "cavewall 0.1\n");  // CMake's project version
    const CliResult help = runCavewall({"--help"});
    EXPECT_THAT(help.out, HasSubstr("commands:\n  view "));
    const CliResult viewHelp = runCavewall({"view", "--help"});
    EXPECT_THAT(viewHelp.out, StartsWith("usage: cavewall view MODEL"));
    EXPECT_THAT(viewHelp.out, HasSubstr("0.15 degrees per pixel"));
}

TEST(ViewCli, BadWordsGiveClearErrors) {
    const struct {
        std::vector<std::string> args;
        std::string message;
    } cases[] = {
        {{"view"}, "missing argument: expected MODEL"},
        {{"view", kRoom, kRoom}, "view: unexpected word '" + kRoom + "' (expected one MODEL, then --flags)"},
        {{"view", kRoom, "--resolution", "640"}, "--resolution: expected WxH with integers in [1, 16384]"},
        {{"view", kRoom, "--start", "middle"}, "--start: expected one of inside, view-all, origin, got 'middle'"},
        {{"view", kRoom, "--headless", "--frames", "1"}, "--tracker desktop: expected --window"},
        {{"view", kRoom, "--save-frames", "all"}, "--save-frames: needs --out DIR"},
        {{"run", "--scene", kRoom, "--tracker", "sim:walk", "--out", "x"}, "--frames: required flag is missing"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.args[0] + " " + (c.args.size() > 2 ? c.args[2] : ""));
        const CliResult r = runCavewall(c.args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

TEST(ViewCli, StartsInsideTheModelAtEyeHeightAndRendersAtTheResolutionAsked) {
    const fs::path out = outputDir("view-headless");
    const CliResult r = runCavewall({"view", kRoom, "--headless", "--tracker", "sim:walk", "--nav", "none", "--frames",
                                     "2", "--resolution", "96x54", "--save-frames", "all", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("view: 2 frames on "));
    const CsvTable rows = readCsv(out / "frames.csv");
    ASSERT_EQ(rows.size(), 2u);
    // The room's floor is at y = 0 and its walls within 5 m of the origin; sim:walk's head
    // stays 1.2-2 m above the CAVE floor, which stands on the room's floor.
    const double y = rows[0].number("world_y");
    EXPECT_GT(y, 1.0);
    EXPECT_LT(y, 2.1);
    EXPECT_LT(std::hypot(rows[0].number("world_x"), rows[0].number("world_z")), 5.0);
    const scenes::Image image = scenes::readImage(out / "frames" / "00000" / "monitor.png");
    EXPECT_EQ(image.width, 96);
    EXPECT_EQ(image.height, 54);
}

TEST(ViewCli, RunStartsAtTheOriginUnlessAskedAndViewAllStepsBack) {
    const auto firstEye = [](const std::string& start) {
        const fs::path out = outputDir("run-start-" + start);
        const CliResult r =
            runCavewall({"run", "--scene", kRoom, "--display", "desktop", "--tracker", "sim:walk", "--nav", "none",
                         "--frames", "1", "--resolution", "32x18", "--start", start, "--out", out.string()});
        EXPECT_EQ(r.exitCode, 0) << r.err;
        const CsvTable rows = readCsv(out / "frames.csv");
        return glm::dvec3(rows[0].number("world_x"), rows[0].number("world_y"), rows[0].number("world_z"));
    };
    const glm::dvec3 origin = firstEye("origin"), all = firstEye("view-all");
    // The origin start has the CAVE at the world origin: the eye is the tracked head (within
    // a metre of the origin); view-all steps back (+Z) until the whole room is in view.
    EXPECT_LT(std::hypot(origin.x, origin.z), 1.0);
    EXPECT_GT(all.z, origin.z + 3.0);
}

}  // namespace
}  // namespace cavewall::test
