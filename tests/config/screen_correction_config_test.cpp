// The display configuration's projector correction keys: warp, blend and blackLevel.
#include "config/display_config.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

namespace cavewall::config {
namespace {

using ::testing::HasSubstr;

std::string withScreen(const std::string& extra) {
    return R"({"screens": [{"name": "front", "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5],
        "upperLeft": [-1.5, 3, -1.5], "resolution": [64, 64])" +
           extra + "}]}";
}

TEST(ScreenCorrectionConfig, KeysAreOptionalAndParsed) {
    const DisplayConfig none = parseDisplayConfig(withScreen(""), "lab.json");
    EXPECT_FALSE(none.screens[0].corrected());  // no keys: no correction pass at all
    const DisplayConfig c = parseDisplayConfig(
        withScreen(R"(, "warp": "front.pfm", "blend": "masks/front.png", "blackLevel": [0.01, 0.02, 0.03])"),
        "lab.json");
    const Screen& s = c.screens[0];
    EXPECT_EQ(s.warp, "front.pfm");
    EXPECT_EQ(s.blend, "masks/front.png");
    EXPECT_EQ(s.blackLevel, glm::dvec3(0.01, 0.02, 0.03));
    EXPECT_TRUE(s.corrected());
    // A scalar black level is grey.
    EXPECT_EQ(parseDisplayConfig(withScreen(R"(, "blackLevel": 0.5)"), "lab.json").screens[0].blackLevel,
              glm::dvec3(0.5));
}

TEST(ScreenCorrectionConfig, BadValuesHaveTheirMessage) {
    struct Case {
        const char* name;
        const char* extra;
        const char* message;
    };
    const Case cases[] = {
        {"empty warp", R"(, "warp": "")", "screens[0].warp: expected a file path relative to the configuration"},
        {"warp not a string", R"(, "warp": 3)", "screens[0].warp: expected a string"},
        {"black level above 1", R"(, "blackLevel": 1.5)",
         "screens[0].blackLevel: expected a number in [0, 1], got 1.5"},
        {"black level of two", R"(, "blackLevel": [0.1, 0.2])", "screens[0].blackLevel: expected an array of 3"},
        {"negative channel", R"(, "blackLevel": [0, -0.1, 0])",
         "screens[0].blackLevel[1]: expected a number in [0, 1], got -0.1"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT([&] { parseDisplayConfig(withScreen(c.extra), "lab.json"); },
                    ThrowsMessage<Error>(HasSubstr(c.message)));
    }
}

TEST(ScreenCorrectionConfig, FilesAreFoundBesideTheConfiguration) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "cavewall-correction-config";
    std::filesystem::create_directories(dir);
    const std::filesystem::path config = dir / "lab.json";
    std::ofstream(config) << withScreen(R"(, "warp": "front.warp")");
    std::filesystem::remove(dir / "front.warp");
    EXPECT_THAT(
        [&] { loadDisplayConfig(config.string()); },
        ThrowsMessage<Error>(HasSubstr("screens[0] 'front': warp file 'front.warp' not found (expected a file at " +
                                       (dir / "front.warp").string())));
    std::ofstream(dir / "front.warp") << "cavewall-warp 1\n";
    const DisplayConfig c = loadDisplayConfig(config.string());
    EXPECT_EQ(c.directory, dir);
    EXPECT_EQ(screenFilePath(c, c.screens[0].warp), dir / "front.warp");
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace cavewall::config
