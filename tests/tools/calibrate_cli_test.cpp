#include "config/display_config.h"
#include "tests/support/run_cli.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// A folder of its own per test under the build tree, emptied first.
fs::path workFolder(const std::string& name) {
    const fs::path dir = fs::path(CAVEWALL_BINARY_DIR) / "tests" / "calibrate_cli" / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    return dir;
}

// The eight corners of cave4 (a 3 m cube on the floor centre) and where a tracker whose frame
// is turned 120° about +Y and moved by (0.4, -1.1, 2) sees them, within 0.5 mm.
const glm::dvec3 kTranslation(0.4, -1.1, 2.0);
glm::dmat4 trueCaveFromTracker() {
    glm::dmat4 m = glm::mat4_cast(glm::angleAxis(glm::radians(120.0), glm::dvec3(0, 1, 0)));
    m[3] = glm::dvec4(kTranslation, 1.0);
    return m;
}

nlohmann::json pairsJson(int count) {
    const glm::dmat4 trackerFromCave = glm::inverse(trueCaveFromTracker());
    nlohmann::json pairs = nlohmann::json::array();
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 cave(i & 1 ? 1.5 : -1.5, i & 2 ? 3.0 : 0.0, i & 4 ? 1.5 : -1.5);
        // A fixed, deterministic measurement error of at most 0.5 mm per coordinate.
        const glm::dvec3 t = glm::dvec3(trackerFromCave * glm::dvec4(cave, 1.0)) +
                             0.0005 * glm::dvec3((i % 3) - 1, ((i + 1) % 3) - 1, ((i + 2) % 3) - 1);
        pairs.push_back({{"tracker", {t.x, t.y, t.z}}, {"cave", {cave.x, cave.y, cave.z}}, {"label", "corner"}});
    }
    return {{"pairs", pairs}};
}

fs::path writeFile(const fs::path& path, const std::string& text) {
    std::ofstream(path) << text;
    return path;
}

TEST(CalibrateCli, WritesAConfigThatLoadsAndMapsThePoints) {
    const fs::path dir = workFolder("fit");
    const nlohmann::json pairs = pairsJson(8);
    const fs::path pairsFile = writeFile(dir / "pairs.json", pairs.dump());
    const fs::path out = dir / "lab.json";
    const CliResult r =
        runCavewall({"calibrate", "--pairs", pairsFile.string(), "--display", "cave4", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("rms_mm "));
    EXPECT_THAT(r.out, HasSubstr("yaw_deg 120.0"));  // the turn of the tracker frame
    const config::DisplayConfig c = config::loadDisplayConfig(out.string());
    EXPECT_EQ(c.screens, config::loadDisplayConfig("cave4").screens);  // only the calibration changes
    for (const auto& p : pairs["pairs"]) {
        const glm::dvec3 t(p["tracker"][0], p["tracker"][1], p["tracker"][2]);
        const glm::dvec3 cave(p["cave"][0], p["cave"][1], p["cave"][2]);
        // Each point carries at most sqrt(3) x 0.5 mm of error; the fit spreads it, so every
        // point maps within 1 mm of its mark.
        EXPECT_LT(glm::distance(glm::dvec3(c.tracking.caveFromTracker * glm::dvec4(t, 1.0)), cave), 0.001);
    }
    EXPECT_LT(glm::distance(glm::dvec3(c.tracking.caveFromTracker[3]), kTranslation), 0.001);
}

TEST(CalibrateCli, PrintsTheExpectedErrorAndAdvisesOnPoorlySpreadPoints) {
    const fs::path dir = workFolder("spread");
    // The eight corners of cave4: the best spread, no advice.
    const fs::path eight = writeFile(dir / "eight.json", pairsJson(8).dump());
    CliResult r = runCavewall(
        {"calibrate", "--pairs", eight.string(), "--display", "cave4", "--out", (dir / "eight-out.json").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("noise_mm "));
    EXPECT_THAT(r.out, HasSubstr("expected_error_rms_mm "));
    EXPECT_THAT(r.out, HasSubstr("expected_error_corner_mm "));
    EXPECT_THAT(r.err, ::testing::Not(HasSubstr("poorly spread")));
    // The four corners of the front wall fix the depth direction poorly: advice, and the file
    // is still written.
    const fs::path four = writeFile(dir / "four.json", pairsJson(4).dump());
    r = runCavewall(
        {"calibrate", "--pairs", four.string(), "--display", "cave4", "--out", (dir / "four-out.json").string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.err, HasSubstr("four.json: the points are poorly spread over the volume the screens enclose: the "
                                 "expected error over it is 1.29 times the noise per coordinate"));
    EXPECT_TRUE(fs::exists(dir / "four-out.json"));
}

TEST(CalibrateCli, PlacesMeasuredScreens) {
    const fs::path dir = workFolder("screens");
    // The front wall really stands 5 cm further back than cave4 says; its corners are measured.
    const glm::dmat4 trackerFromCave = glm::inverse(trueCaveFromTracker());
    auto tracked = [&](double x, double y) {
        const glm::dvec3 t(trackerFromCave * glm::dvec4(x, y, -1.55, 1.0));
        return nlohmann::json{t.x, t.y, t.z};
    };
    nlohmann::json pairs = pairsJson(8);
    pairs["screens"] = {
        {"front", {{"lowerLeft", tracked(-1.5, 0)}, {"lowerRight", tracked(1.5, 0)}, {"upperLeft", tracked(-1.5, 3)}}}};
    const fs::path pairsFile = writeFile(dir / "pairs.json", pairs.dump());
    const fs::path out = dir / "lab.json";
    const CliResult r =
        runCavewall({"calibrate", "--pairs", pairsFile.string(), "--display", "cave4", "--out", out.string()});
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("screen front: lowerLeft moved 50.0 mm"));
    const config::DisplayConfig c = config::loadDisplayConfig(out.string());
    // Within the fit's error (under 1 mm, as above).
    EXPECT_LT(glm::distance(c.screens[0].lowerLeft, glm::dvec3(-1.5, 0, -1.55)), 0.001);
    EXPECT_LT(glm::distance(c.screens[0].lowerRight, glm::dvec3(1.5, 0, -1.55)), 0.001);
    EXPECT_LT(glm::distance(c.screens[0].upperLeft, glm::dvec3(-1.5, 3, -1.55)), 0.001);
    EXPECT_EQ(c.screens[1], config::loadDisplayConfig("cave4").screens[1]);  // the others stay

    pairs["screens"] = {{"back", pairs["screens"]["front"]}};
    const fs::path unknown = writeFile(dir / "unknown.json", pairs.dump());
    const CliResult bad = runCavewall(
        {"calibrate", "--pairs", unknown.string(), "--display", "cave4", "--out", (dir / "bad.json").string()});
    EXPECT_EQ(bad.exitCode, 1);
    EXPECT_THAT(bad.err, HasSubstr(unknown.string() + ": screens.back: no such screen in "));
    EXPECT_THAT(bad.err, HasSubstr("cave4.json (expected one of: front, left, right, floor)"));
    EXPECT_FALSE(fs::exists(dir / "bad.json"));
}

TEST(CalibrateCli, RefusesBadInputWithItsMessage) {
    const fs::path dir = workFolder("refusals");
    const fs::path good = writeFile(dir / "good.json", pairsJson(8).dump());
    const fs::path two = writeFile(dir / "two.json", pairsJson(2).dump());
    nlohmann::json collinear = pairsJson(3);
    collinear["pairs"][2]["cave"] = {0.0, 0.0, -1.5};  // between the first two marks
    const fs::path line = writeFile(dir / "line.json", collinear.dump());
    const fs::path display = writeFile(dir / "display.json", R"({"screens": [{"name": "front",
        "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, 3, -1.5],
        "resolution": [1024, 1024]}]})");
    struct Case {
        const char* name;
        std::vector<std::string> args;
        std::string message;
    };
    const std::string out = (dir / "out.json").string();
    const Case cases[] = {
        {"two pairs",
         {"--pairs", two.string(), "--display", "cave4", "--out", out},
         two.string() + ": expected at least 3 pairs, got 2"},
        {"collinear",
         {"--pairs", line.string(), "--display", "cave4", "--out", out},
         line.string() + ": the cave points are collinear: their spread across their common line is 0.0 mm, "
                         "expected at least 10.0 mm"},
        {"over the input",
         {"--pairs", good.string(), "--display", display.string(), "--out", display.string()},
         "--out: '" + display.string() + "' is the input file"},
        {"over the pairs",
         {"--pairs", good.string(), "--display", "cave4", "--out", good.string()},
         "--out: '" + good.string() + "' is the input file"},
        {"a folder",
         {"--pairs", good.string(), "--display", "cave4", "--out", dir.string()},
         "--out: '" + dir.string() + "' is not a regular file"},
        {"missing out", {"--pairs", good.string(), "--display", "cave4"}, "--out"},
        {"bad noise", {"--pairs", good.string(), "--display", "cave4", "--out", out, "--noise", "0"}, "--noise"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        std::vector<std::string> args{"calibrate"};
        args.insert(args.end(), c.args.begin(), c.args.end());
        const CliResult r = runCavewall(args);
        EXPECT_EQ(r.exitCode, 1);
        EXPECT_THAT(r.err, HasSubstr(c.message));
        EXPECT_FALSE(fs::exists(out));
    }
}

}  // namespace
}  // namespace cavewall::test
