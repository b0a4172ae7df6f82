#include "config/display_config.h"
#include "config/display_config_writer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::config {
namespace {

// parse(write(c)) == c, field for field (DisplayConfig's operator== compares every double
// exactly), and writing again gives the same text.
void expectRoundTrip(const DisplayConfig& c) {
    const std::string text = displayConfigJson(c);
    DisplayConfig back = parseDisplayConfig(text, "written.json");
    back.directory = c.directory;  // where the file was read from is not part of its text
    EXPECT_EQ(back, c) << text;
    EXPECT_EQ(displayConfigJson(back), text);
    validateDisplayConfig(back, "written.json");
}

TEST(DisplayConfigWriter, PresetsRoundTrip) {
    for (const char* preset : {"cave4", "cave6", "powerwall", "desktop"}) {
        SCOPED_TRACE(preset);
        expectRoundTrip(loadDisplayConfig(preset));
    }
}

TEST(DisplayConfigWriter, EveryFieldRoundTrips) {
    // Every optional field away from its default, numbers that need all 17 digits, an
    // orientation from angles (a quaternion that is unit only to rounding) and a scaled
    // calibration with an odd rotation.
    const DisplayConfig c = parseDisplayConfig(
        R"({"name": "lab", "screens": [
              {"name": "a", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5], "upperLeft": [-1.5, 3, -1.5],
               "resolution": [1920, 1080], "rank": 2,
               "output": {"window": {"monitor": 1, "position": [-10, 20], "size": [800, 600], "fullscreen": true,
                                     "borderless": true, "resize": "reframe"}}},
              {"name": "b", "lowerLeft": [0.1, 0.2, -2], "lowerRight": [0.30000000000000004, 0.2, -2],
               "upperLeft": [0.1, 0.4, -2], "resolution": [10, 10], "output": {"headless": {"file": "b-file"}},
               "warp": "warp/b.pfm", "blend": "b-blend.png", "blackLevel": [0.01, 0.02, 0.030000000000000002]},
              {"name": "c", "lowerLeft": [-1, 0, -3], "lowerRight": [1, 0, -3], "upperLeft": [-1, 1, -3],
               "resolution": [10, 5], "output": {"window": {}}, "warp": "c.warp", "blackLevel": 0.015}],
            "viewer": {"headPosition": [0.1, 1.6, 0.2], "headOrientation": {"yawDeg": 33, "pitchDeg": -7, "rollDeg": 2},
                       "eyeSeparation": 0.0635, "near": 0.01, "far": "infinite"},
            "stereo": "quad-buffer", "minEyeDistance": 0.002,
            "tracking": {"caveFromTracker": [[0.8660254037844387, 0, 0.5, 0.1], [0, 1, 0, -0.2],
                                             [-0.5, 0, 0.8660254037844387, 1.5], [0, 0, 0, 1]],
                         "latencyMs": 12.5, "volume": [[-3, -1, -3], [3, 4, 3]]}})",
        "lab.json");
    expectRoundTrip(c);
    DisplayConfig scaled = c;
    scaled.tracking.caveFromTracker =
        glm::dmat4(1.0137 * glm::mat3_cast(glm::angleAxis(2.9, glm::normalize(glm::dvec3(1, -2, 0.3)))));
    scaled.tracking.caveFromTracker[3] = glm::dvec4(0.123456789, -1.0 / 3.0, 2.0, 1.0);
    scaled.viewer.far = 250.0;
    expectRoundTrip(scaled);
}

TEST(DisplayConfigWriter, LeavesOutOptionalKeysAtTheirDefault) {
    const std::string text = displayConfigJson(loadDisplayConfig("cave4"));
    EXPECT_EQ(text.find("\"rank\""), std::string::npos);
    EXPECT_EQ(text.find("\"output\""), std::string::npos);
    EXPECT_EQ(text.find("\"volume\""), std::string::npos);
    // Numbers on one line per vector, one row of the calibration per line.
    EXPECT_THAT(text, ::testing::HasSubstr("\"lowerLeft\": [-1.5, 0.0, -1.5]"));
    EXPECT_THAT(text, ::testing::HasSubstr("\n      [1.0, 0.0, 0.0, 0.0],\n"));
}

}  // namespace
}  // namespace cavewall::config
