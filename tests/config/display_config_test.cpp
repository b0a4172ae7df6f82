#include "config/display_config.h"
#include "config/display_limits.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>

namespace cavewall::config {
namespace {

using ::testing::HasSubstr;

// A valid one-screen configuration; the cases below break one thing at a time.
const char* const kScreen =
    R"({"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5],
        "upperLeft": [-1.5, 3, -1.5], "resolution": [1024, 1024]})";

std::string withScreens(const std::string& screens, const std::string& extra = "") {
    return R"({"screens": [)" + screens + "]" + extra + "}";
}

DisplayConfig load(const std::string& text) {
    DisplayConfig c = parseDisplayConfig(text, "lab.json");
    validateDisplayConfig(c, "lab.json");
    return c;
}

TEST(DisplayConfig, MinimalScreenGetsDefaults) {
    const DisplayConfig c = load(withScreens(kScreen));
    ASSERT_EQ(c.screens.size(), 1u);
    EXPECT_EQ(c.name, "lab");  // the file stem
    EXPECT_EQ(c.screens[0].resolution, glm::ivec2(1024, 1024));
    EXPECT_FALSE(c.screens[0].window.has_value());  // headless unless a window is asked for
    EXPECT_EQ(c.viewer.eyeSeparation, 0.064);
    EXPECT_EQ(c.stereo, StereoMode::Mono);
    EXPECT_EQ(c.tracking.caveFromTracker, glm::dmat4(1.0));
}

TEST(DisplayConfig, ParsesEveryField) {
    const DisplayConfig c = load(withScreens(
        R"({"name": "w", "lowerLeft": [0,0,0], "lowerRight": [2,0,0], "upperLeft": [0,1,0],
            "resolution": [640, 320],
            "output": {"window": {"monitor": 1, "position": [10, 20], "size": [320, 160], "fullscreen": true,
                                  "borderless": true, "resize": "reframe"}}})",
        R"(, "viewer": {"headPosition": [0, 1.6, 1], "headOrientation": {"yawDeg": 90},
                        "eyeSeparation": 0.07, "near": 0.1, "far": "infinite"},
             "stereo": "side-by-side", "minEyeDistance": 0.01,
             "tracking": {"caveFromTracker": [[1,0,0,0.5],[0,1,0,0],[0,0,1,-2],[0,0,0,1]], "latencyMs": 20})"));
    const Screen& s = c.screens[0];
    ASSERT_TRUE(s.window.has_value());
    EXPECT_EQ(*s.window, (WindowOutput{1, glm::ivec2(10, 20), {320, 160}, true, true, true}));
    EXPECT_EQ(c.viewer.headPosition, glm::dvec3(0, 1.6, 1));
    // Yaw 90° turns -Z (forward) into -X.
    const glm::dvec3 forward = c.viewer.headOrientation * glm::dvec3(0, 0, -1);
    EXPECT_NEAR(forward.x, -1.0, 1e-12);
    EXPECT_TRUE(std::isinf(c.viewer.far));
    EXPECT_EQ(c.stereo, StereoMode::SideBySide);
    EXPECT_EQ(c.minEyeDistance, 0.01);
    // Rows as written: the translation is the last column.
    EXPECT_EQ(c.tracking.caveFromTracker[3], glm::dvec4(0.5, 0, -2, 1));
    EXPECT_EQ(c.tracking.latencyMs, 20.0);
}

TEST(DisplayConfig, CalibrationMayCarryAUniformScale) {
    // A 1 % scale, as a calibration fitted with `cavewall calibrate --scale` gives, times a
    // rotation of 90° about +Y.
    const DisplayConfig c = load(withScreens(
        kScreen, R"(, "tracking": {"caveFromTracker": [[0,0,1.01,0],[0,1.01,0,0],[-1.01,0,0,0],[0,0,0,1]]})"));
    EXPECT_EQ(c.tracking.caveFromTracker[1], glm::dvec4(0, 1.01, 0, 0));
}

struct BadCase {
    const char* name;
    std::string json;
    const char* message;
};

TEST(DisplayConfig, EveryRuleHasItsMessage) {
    const BadCase cases[] = {
        {"not JSON", "{\"screens\": [", "lab.json: not valid JSON: at line 1"},
        {"no screens", "{}", "lab.json: missing required key 'screens'"},
        {"empty screens", withScreens(""), "lab.json: screens: expected an array of 1 to 256 elements, got 0"},
        {"unknown top key", withScreens(kScreen, R"(, "stero": "mono")"),
         "lab.json: unknown key 'stero' (expected one of: name, screens, viewer"},
        {"unknown screen key", withScreens(R"({"name": "a", "lowerleft": [0,0,0]})"),
         "lab.json: screens[0]: unknown key 'lowerleft'"},
        {"missing corner",
         withScreens(R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "resolution": [1,1]})"),
         "screens[0]: missing required key 'upperLeft'"},
        {"corner of two numbers",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1]})"),
         "screens[0].lowerLeft: expected an array of 3 elements, got 2"},
        {"string in corner",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,"x",0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1]})"),
         "screens[0].lowerLeft[1]: expected a number, got \"x\""},
        {"number overflow",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,1e999,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1]})"),
         "lab.json: not valid JSON: number overflow parsing '1e999'"},
        {"zero resolution",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [0,768]})"),
         "screens[0].resolution[0]: expected an integer in [1, 16384], got 0"},
        {"negative resolution",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1024,-1]})"),
         "screens[0].resolution[1]: expected an integer in [1, 16384], got -1"},
        {"fractional resolution",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [10.5,1]})"),
         "screens[0].resolution[0]: expected an integer, got 10.5"},
        {"zero window size",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1], "output": {"window": {"size": [0, 10]}}})"),
         "screens[0].output.window.size[0]: expected an integer in [1, 16384], got 0"},
        {"unknown resize",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1], "output": {"window": {"resize": "stretch"}}})"),
         "screens[0].output.window.resize: expected one of \"letterbox\", \"reframe\", got \"stretch\""},
        {"both outputs",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1], "output": {"window": {}, "headless": {}}})"),
         "screens[0].output: expected exactly one of 'window' or 'headless'"},
        {"empty name",
         withScreens(
             R"({"name": "", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0,1,0], "resolution": [1,1]})"),
         "screens[0].name: expected a name of 1 to 64 characters (it names an output file), got 0"},
        {"collinear corners",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [2,0,0], "resolution": [1,1]})"),
         "lab.json: screens[0] 'a': corners are collinear (expected a non-zero area, got 0 m²)"},
        {"zero width",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [0,0,0], "upperLeft": [0,1,0], "resolution": [1,1]})"),
         "screens[0] 'a': screen is degenerate (expected width and height of at least 0.0001 m, got 0 m × 1 m"},
        {"not a rectangle",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1,0,0], "upperLeft": [0.1,1,0], "resolution": [1,1]})"),
         "screens[0] 'a': corners are not a rectangle (expected the edges at lowerLeft to meet at 90° ± 0.1°, got "
         "84.2894°)"},
        {"duplicate names", withScreens(std::string(kScreen) + "," + kScreen),
         "lab.json: screens[1] 'front': duplicate screen name"},
        {"eye separation too large", withScreens(kScreen, R"(, "viewer": {"eyeSeparation": 0.5})"),
         "viewer.eyeSeparation: expected a number in [0, 0.2], got 0.5"},
        {"negative eye separation", withScreens(kScreen, R"(, "viewer": {"eyeSeparation": -0.01})"),
         "viewer.eyeSeparation: expected a number in [0, 0.2], got -0.01"},
        {"near zero", withScreens(kScreen, R"(, "viewer": {"near": 0})"),
         "viewer.near: expected a number in [1e-06, 1e+06], got 0"},
        {"far as a word", withScreens(kScreen, R"(, "viewer": {"far": "forever"})"),
         "viewer.far: expected one of \"infinite\", got \"forever\""},
        {"near not below far", withScreens(kScreen, R"(, "viewer": {"near": 10, "far": 10})"),
         "lab.json: viewer: near must be less than far (got near 10 m, far 10 m)"},
        {"unknown stereo", withScreens(kScreen, R"(, "stereo": "checkerboard")"),
         "stereo: expected one of \"mono\", \"separate\", \"side-by-side\", \"top-bottom\", \"anaglyph\", "
         "\"quad-buffer\", got \"checkerboard\""},
        {"non-uniform scale in the calibration",
         withScreens(kScreen, R"(, "tracking": {"caveFromTracker": [[2,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})"),
         "tracking.caveFromTracker: expected a rotation, or a rotation times a uniform scale, in the upper 3x3 "
         // det 2 gives the scale 2^(1/3) = 1.25992; the x axis is then 2 / 1.25992 = 1.5874 long, and
         // its squared length 2.51984 is 1.51984 away from 1.
         "(orthonormal within 1e-4 after dividing by the scale 1.25992), got an error of 1.51984"},
        {"calibration scale too large",
         withScreens(kScreen, R"(, "tracking": {"caveFromTracker": [[3,0,0,0],[0,3,0,0],[0,0,3,0],[0,0,0,1]]})"),
         "tracking.caveFromTracker: expected a rotation, or a rotation times a uniform scale in [0.5, 2], in the "
         "upper 3x3, got det 27"},
        {"mirrored calibration",
         withScreens(kScreen, R"(, "tracking": {"caveFromTracker": [[-1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})"),
         "got det -1 (a reflection)"},
        {"projective calibration",
         withScreens(kScreen, R"(, "tracking": {"caveFromTracker": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,1,1]]})"),
         "tracking.caveFromTracker: expected the last row to be [0, 0, 0, 1]"},
        {"screen facing away from the head",
         withScreens(
             R"({"name": "left", "lowerLeft": [-1.5,0,-1.5], "lowerRight": [-1.5,0,1.5], "upperLeft": [-1.5,3,-1.5], "resolution": [1,1]})"),
         "lab.json: screens[0] 'left': faces away from the default head [0, 1.7, 0] (its front, "
         "lowerLeft->lowerRight x lowerLeft->upperLeft, points to [-1, 0, 0]; the head is 1.5 m behind it); expected "
         "the head in front: swap lowerLeft with lowerRight"},
        {"bad quaternion", withScreens(kScreen, R"(, "viewer": {"headOrientation": [0, 0, 0, 0]})"),
         "viewer.headOrientation: expected a unit quaternion [x, y, z, w], got length 0"},
    };
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { load(c.json); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

// A screen with `name` and headless output `file` (hostile input: names that become paths).
std::string named(const std::string& name, const std::string& file = "") {
    return R"({"name": ")" + name + R"(", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5],
        "upperLeft": [-1.5, 3, -1.5], "resolution": [64, 64])" +
           (file.empty() ? "" : R"(, "output": {"headless": {"file": ")" + file + R"("}})") + "}";
}

TEST(DisplayConfig, NamesThatBecomeFilesFollowTheRule) {
    const BadCase cases[] = {
        {"parent folder", withScreens(named("../../escaped-name")),
         "lab.json: screens[0].name: expected only letters, digits, '_', '-' and '.' (it names an output file), "
         "got '../../escaped-name'"},
        {"headless file up", withScreens(named("front", "../../x")),
         "screens[0].output.headless.file: expected only letters, digits, '_', '-' and '.' (it names an output file), "
         "got '../../x'"},
        {"absolute headless file", withScreens(named("front", "/tmp/x")),
         "screens[0].output.headless.file: expected only"},
        {"NUL in name", withScreens(named("a\\u0000b")),
         "screens[0].name: expected only letters, digits, '_', '-' and "
         "'.' (it names an output file), got 'a\\x00b'"},
        {"hidden", withScreens(named(".front")),
         "screens[0].name: expected a name that does not start with '.' or '-'"},
        {"dot dot", withScreens(named("front", "..")),
         "screens[0].output.headless.file: expected a name that does not "
         "start with '.' or '-'"},
        {"fold-out", withScreens(named("foldout")),
         "screens[0].name: the name 'foldout' is reserved for the program's own output files (expected another name)"},
        {"fold-out any case", withScreens(named("front", "FoldOut")), "the name 'FoldOut' is reserved"},
        {"too long", withScreens(named(std::string(65, 'a'))),
         "screens[0].name: expected a name of 1 to 64 characters (it names an output file), got 65"},
        {"file of another screen", withScreens(named("front") + "," + named("floor", "Front")),
         "lab.json: screens[1] 'floor': image file 'front' is also another screen's"},
    };
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { load(c.json); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    EXPECT_NO_THROW(load(withScreens(named("upper-left_2.a", "Front.wall"))));
}

TEST(DisplayConfig, MagnitudesAreWithinAStatedRange) {
    const BadCase cases[] = {
        {"corner at 1e308",
         withScreens(
             R"({"name": "a", "lowerLeft": [0,0,0], "lowerRight": [1e308,0,0], "upperLeft": [0,1,0], "resolution": [1,1]})"),
         "lab.json: screens[0].lowerRight: expected coordinates in [-1000, 1000] m, got [1e+308, 0, 0]"},
        {"head at 1e308", withScreens(kScreen, R"(, "viewer": {"headPosition": [0, 1e308, 0]})"),
         "lab.json: viewer.headPosition: expected coordinates in [-1000, 1000] m, got [0, 1e+308, 0]"},
        {"calibration far away",
         withScreens(kScreen, R"(, "tracking": {"caveFromTracker": [[1,0,0,1e9],[0,1,0,0],[0,0,1,0],[0,0,0,1]]})"),
         "lab.json: tracking.caveFromTracker: expected a translation within 1000 m, got 1e+09 m"},
    };
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { load(c.json); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
    // The same rule holds for configurations built in code.
    DisplayConfig c = load(withScreens(kScreen));
    c.screens[0].upperLeft.y = 1e300;
    EXPECT_THAT(
        [&] { validateDisplayConfig(c, "code"); },
        ThrowsMessage<Error>(HasSubstr("code: screens[0] 'front': corner [-1.5, 1e+300, -1.5] is out of range")));
}

// The plausible tracking volume is a configuration key; without it the default box around the
// screens applies.
TEST(DisplayConfig, TrackingVolumeIsAKeyWithItsRules) {
    const DisplayConfig set = load(withScreens(kScreen, R"(, "tracking": {"volume": [[-2, 0, -2], [2, 2.5, 2]]})"));
    ASSERT_TRUE(set.tracking.volume);
    EXPECT_EQ(trackingVolumeOf(set).min, glm::dvec3(-2, 0, -2));
    EXPECT_EQ(trackingVolumeOf(set).max, glm::dvec3(2, 2.5, 2));
    const DisplayConfig unset = load(withScreens(kScreen));
    EXPECT_FALSE(unset.tracking.volume);
    EXPECT_EQ(trackingVolumeOf(unset).min, glm::dvec3(-3.5, -2, -3.5));
    const BadCase cases[] = {
        {"one corner", withScreens(kScreen, R"(, "tracking": {"volume": [[0, 0, 0]]})"),
         "lab.json: tracking.volume: expected an array of 2 elements, got 1"},
        {"inverted", withScreens(kScreen, R"(, "tracking": {"volume": [[0, 3, 0], [1, 2, 1]]})"),
         "lab.json: tracking.volume: expected the first corner below the second on every axis, got y 3 >= 2"},
        {"far away", withScreens(kScreen, R"(, "tracking": {"volume": [[0, 0, 0], [1, 1, 1e9]]})"),
         "lab.json: tracking.volume[1]: expected coordinates within 1000 m, got 1e+09 m"},
    };
    for (const BadCase& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { load(c.json); }, ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(DisplayConfig, JsonNestedThousandsDeepIsRefused) {
    const std::string deep = withScreens(kScreen, R"(, "name": )" + std::string(5000, '[') + std::string(5000, ']'));
    EXPECT_THAT([&] { load(deep); }, ThrowsMessage<Error>(HasSubstr("lab.json: JSON is nested too deeply at byte")));
}

TEST(DisplayConfig, ScreensAreDealtToClusterRanks) {
    DisplayConfig c = loadDisplayConfig("cave4");
    // Round-robin by index: 4 screens on 3 ranks.
    EXPECT_EQ(screensOfRank(c, 0, 3), (std::vector<int>{0, 3}));
    EXPECT_EQ(screensOfRank(c, 2, 3), (std::vector<int>{2}));
    c.screens[3].rank = 1;  // an explicit rank wins
    EXPECT_EQ(screensOfRank(c, 1, 3), (std::vector<int>{1, 3}));
    EXPECT_THAT([&] { screensOfRank(c, 0, 1); },
                ThrowsMessage<Error>(HasSubstr("screens[3] 'floor': rank 1 does not exist (expected a rank below 1")));
}

TEST(DisplayConfig, NaNCannotBeWrittenInJson) {
    // JSON has no NaN literal; the parser rejects it with a position.
    EXPECT_THAT([] { load(withScreens(kScreen, R"(, "minEyeDistance": NaN)")); },
                ThrowsMessage<Error>(HasSubstr("lab.json: not valid JSON: at line 2")));
}

TEST(DisplayConfig, SlightlyOffSquareScreenWithinToleranceIsAccepted) {
    // 0.05° off square is inside the stated 0.1° tolerance.
    const double dx = std::tan(glm::radians(0.05));
    const std::string s = R"({"name": "a", "lowerLeft": [0,0,-1], "lowerRight": [1,0,-1], "upperLeft": [)" +
                          std::to_string(dx) + R"(,1,-1], "resolution": [1,1]})";
    EXPECT_NO_THROW(load(withScreens(s)));
}

TEST(DisplayConfig, NonSquarePixelsAndTiltedScreensAreWarnedWithTheFigure) {
    // 3 m x 3 m at 1024 x 768: pixels 0.75 times as wide as high.
    const DisplayConfig wide = load(withScreens(
        R"({"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5],
            "upperLeft": [-1.5, 3, -1.5], "resolution": [1024, 768]})"));
    EXPECT_THAT(displayWarnings(wide, "lab.json"),
                ::testing::ElementsAre(HasSubstr("lab.json: screens[0] 'front': pixels are not square: 3.000 x 3.000 m "
                                                 "at 1024 x 768 pixels gives pixels 0.750 times as wide as high")));
    // Leaning back by 10 degrees: the upper edge 3 sin 10 deg further away.
    const double back = 3.0 * std::sin(glm::radians(10.0)), high = 3.0 * std::cos(glm::radians(10.0));
    const DisplayConfig leaning = load(withScreens(
        R"({"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, )" +
        std::to_string(high) + ", " + std::to_string(-1.5 - back) + R"(], "resolution": [1024, 1024]})"));
    EXPECT_THAT(
        displayWarnings(leaning, "lab.json"),
        ::testing::ElementsAre(HasSubstr("screens[0] 'front': tilted 10.0 deg from upright (80.0 deg from flat)")));
    // Rolled: the bottom edge rises 2 degrees; the corners stay a rectangle.
    const double rise = 3.0 * std::sin(glm::radians(2.0)), run = 3.0 * std::cos(glm::radians(2.0));
    const DisplayConfig rolled = load(withScreens(R"({"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [)" +
                                                  std::to_string(-1.5 + run) + ", " + std::to_string(rise) +
                                                  R"(, -1.5], "upperLeft": [)" + std::to_string(-1.5 - rise) + ", " +
                                                  std::to_string(run) + R"(, -1.5], "resolution": [1024, 1024]})"));
    EXPECT_THAT(displayWarnings(rolled, "lab.json"),
                ::testing::ElementsAre(HasSubstr("screens[0] 'front': the bottom edge rises 2.0 deg")));
    // The presets are square, upright or flat: no warning.
    for (const char* preset : {"cave4", "cave6", "powerwall", "desktop"})
        EXPECT_THAT(displayWarnings(loadDisplayConfig(preset), preset), ::testing::IsEmpty()) << preset;
}

TEST(DisplayConfig, UnreadableFileNamesTheFile) {
    EXPECT_THAT([] { loadDisplayConfig("/nonexistent/lab.json"); },
                ThrowsMessage<Error>(HasSubstr("/nonexistent/lab.json: cannot open the file")));
    EXPECT_THAT([] { loadDisplayConfig("cave5"); },
                ThrowsMessage<Error>(HasSubstr("cave5: no such display configuration")));
}

TEST(DisplayConfig, BinaryGarbageFileIsNotJson) {
    const auto path = std::filesystem::temp_directory_path() / "cavewall_garbage.json";
    std::ofstream(path, std::ios::binary) << std::string("\x89PNG\r\n\x1a\n\0\0", 10);
    EXPECT_THAT([&] { loadDisplayConfig(path.string()); },
                ThrowsMessage<Error>(HasSubstr("cavewall_garbage.json: not valid JSON")));
    std::filesystem::remove(path);
}

TEST(DisplayConfig, PresetsLoadWithTheDocumentedGeometry) {
    const DisplayConfig cave4 = loadDisplayConfig("cave4");
    ASSERT_EQ(cave4.screens.size(), 4u);
    EXPECT_EQ(cave4.screens[0].name, "front");
    // The front wall is the 3 m x 3 m square at z = -1.5, floor to 3 m.
    EXPECT_EQ(cave4.screens[0].lowerLeft, glm::dvec3(-1.5, 0, -1.5));
    EXPECT_EQ(cave4.screens[0].upperLeft, glm::dvec3(-1.5, 3, -1.5));
    for (const Screen& s : cave4.screens) {
        SCOPED_TRACE(s.name);
        EXPECT_EQ(s.resolution, glm::ivec2(1024, 1024));
        // Every screen faces the centre of the cube at (0, 1.5, 0).
        const glm::dvec3 n = glm::cross(s.lowerRight - s.lowerLeft, s.upperLeft - s.lowerLeft);
        EXPECT_GT(glm::dot(n, glm::dvec3(0, 1.5, 0) - s.lowerLeft), 0.0);
    }
    // The CAVEs are stereo, one image per eye, at the eye separation of the stereo configs.
    EXPECT_EQ(cave4.stereo, StereoMode::Separate);
    EXPECT_EQ(cave4.viewer.eyeSeparation, 0.064);
    EXPECT_EQ(loadDisplayConfig("cave6").stereo, StereoMode::Separate);
    EXPECT_EQ(loadDisplayConfig("cave6").screens.size(), 6u);
    EXPECT_EQ(loadDisplayConfig("powerwall").screens.size(), 4u);
    const DisplayConfig desk = loadDisplayConfig("desktop");
    ASSERT_EQ(desk.screens.size(), 1u);
    EXPECT_NEAR(glm::length(desk.screens[0].lowerRight - desk.screens[0].lowerLeft), 0.60, 1e-12);
    EXPECT_NEAR(glm::length(desk.screens[0].upperLeft - desk.screens[0].lowerLeft), 0.34, 1e-12);
    // The viewer sits 0.6 m in front of the monitor.
    EXPECT_NEAR(desk.viewer.headPosition.z - desk.screens[0].lowerLeft.z, 0.6, 1e-12);
}

}  // namespace
}  // namespace cavewall::config
