// `cavewall bench SCENE --quick` end to end on a small generated plant (headless GL): every mode
// row is present with finite numbers, and bad input gives clear errors.
#include "tests/cli/run_cli.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

fs::path outputDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    return fs::path(dir ? dir : "/tmp") / "bench_cli";
}

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) out.push_back(field);
    return out;
}

TEST(BenchSceneCli, QuickRunHasEveryModeWithFiniteNumbers) {
    const fs::path root = outputDir();
    const fs::path plant = root / "plant20k";
    // Generated every run: a scene left by an earlier build may come from an older generator.
    const CliResult g = runCavewall({"generate", "plant", "--triangles", "20000", "--out", plant.string()});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const fs::path out = root / "out";
    fs::remove_all(out);
    const CliResult r = runCavewall({"bench", (plant / "scene.json").string(), "--quick", "--frames", "12", "--out",
                                     out.string(), "--cache", (root / "cache").string(), "--alphas", "20,30",
                                     "--warp-alpha", "30"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("| 1 | full |"));
    std::ifstream csv(out / "bench.csv");
    std::string line;
    ASSERT_TRUE(std::getline(csv, line));
    const std::vector<std::string> header = split(line);
    const auto column = [&](const std::string& name) {
        return static_cast<std::size_t>(std::find(header.begin(), header.end(), name) - header.begin());
    };
    const std::size_t lodColumn = column("lod_px"), budgetColumn = column("triangle_budget");
    const std::size_t frameColumn = column("frame_budget_ms");
    ASSERT_LT(frameColumn, header.size());
    std::map<std::string, int> rows;
    while (std::getline(csv, line)) {
        const auto f = split(line);
        ASSERT_EQ(f.size(), header.size()) << line;
        const bool lod = std::strtod(f[lodColumn].c_str(), nullptr) > 0.0;
        const bool budget = std::strtod(f[budgetColumn].c_str(), nullptr) > 0.0;
        const bool frame = std::strtod(f[frameColumn].c_str(), nullptr) > 0.0;
        const std::string key = f[0] + (f[0] == "walls" ? " " + f[1] + " " + f[2] : "") + (lod ? " lod" : "") +
                                (budget ? " budget" : "") + (frame ? " frame" : "");
        ++rows[key];
        SCOPED_TRACE(key);
        for (std::size_t i = 3; i < f.size(); ++i) {
            const double v = std::strtod(f[i].c_str(), nullptr);
            // The reference's PSNR against itself is +infinity; every other number is finite.
            if (header[i] == "psnr_db" && f[0] == "full" && !lod) EXPECT_TRUE(std::isinf(v) && v > 0);
            else EXPECT_TRUE(std::isfinite(v)) << header[i] << " = " << f[i];
            EXPECT_GE(v, 0.0) << header[i];
        }
        EXPECT_GT(std::strtod(f[3].c_str(), nullptr), 0.0) << "frame_ms_p50";
        if (f[0] == "walls") {
            EXPECT_GT(std::strtod(f[14].c_str(), nullptr), 0.0) << "textures";
        }
    }
    // With levels of detail (--lod defaults to 1 px): full, near and every blend mode again,
    // every blend mode with them under a triangle budget, and every blend mode with them held
    // to 60 Hz by the frame-time controller.
    const std::map<std::string, int> expected = {
        {"full", 1}, {"full lod", 1}, {"cells", 1}, {"near", 1}, {"near lod", 1}, {"walls 20 blend", 1},
        {"walls 30 blend", 1}, {"walls 20 blend lod", 1}, {"walls 30 blend lod", 1}, {"walls 30 warp", 1},
        {"walls 30 blend paged", 1}, {"walls 20 blend lod budget", 1}, {"walls 30 blend lod budget", 1},
        {"walls 20 blend lod frame", 1}, {"walls 30 blend lod frame", 1}};
    EXPECT_EQ(rows, expected);
    EXPECT_TRUE(fs::is_regular_file(out / "bench.png"));
    EXPECT_TRUE(fs::is_regular_file(out / "bench.md"));
    // Per screen: every mode times and counts each of cave4's four screens.
    std::ifstream screens(out / "bench_screens.csv");
    ASSERT_TRUE(std::getline(screens, line));
    const std::vector<std::string> columns = split(line);
    ASSERT_EQ(columns[7], "cpu_ms_p50");
    ASSERT_EQ(columns[10], "triangles");
    int screenRows = 0;
    while (std::getline(screens, line)) {
        const auto f = split(line);
        ASSERT_EQ(f.size(), columns.size()) << line;
        EXPECT_GT(std::strtod(f[7].c_str(), nullptr), 0.0) << line;   // every screen was drawn
        EXPECT_TRUE(std::isfinite(std::strtod(f[10].c_str(), nullptr))) << line;
        ++screenRows;
    }
    EXPECT_EQ(screenRows, 15 * 4);
}

TEST(BenchSceneCli, BadInputIsAClearError) {
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const Case cases[] = {
        {{"bench"}, "expected a SCENE or --stability"},
        {{"bench", "x.json", "--frames", "0"}, "--frames"},
        {{"bench", "x.json", "--bogus", "1"}, "bogus"},
        {{"bench", "x.json", "--alphas", "10,abc"}, "--alphas"},
        {{"bench", "x.json", "--alphas", "10,95"}, "expected angles in (0, 90) degrees, got 95"},
        {{"bench", "x.json", "--alphas", ""}, "--alphas"},
        {{"bench", "x.json", "--alphas", "10,30", "--warp-alpha", "20"},
         "--warp-alpha 20 is not one of the planned alphas (10,30); add it to --alphas"},
        {{"bench", (outputDir() / "missing" / "scene.json").string(), "--quick"}, "missing"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.message);
        const CliResult r = runCavewall(c.args);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

}  // namespace
}  // namespace cavewall::test
