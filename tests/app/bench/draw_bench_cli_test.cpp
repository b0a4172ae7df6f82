// `cavewall draw-bench` end to end on a small generated box hall (headless GL): both culling
// configurations are timed, the CSV holds consistent numbers, and bad input is an error.
#include "tests/support/run_cli.h"
#include "tests/support/csv_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <utility>
#include <filesystem>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

fs::path outputDir() {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    return fs::path(dir ? dir : "/tmp") / "draw_bench_cli";
}

TEST(DrawBenchCli, BothCullingModesAndBothLightingsTimedWithConsistentRates) {
    const fs::path root = outputDir();
    const CliResult g = runCavewall({"generate", "boxes", "--triangles", "1200", "--out", (root / "boxes").string()});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const fs::path csvFile = root / "draw.csv";
    fs::remove(csvFile);
    const CliResult r = runCavewall({"draw-bench", (root / "boxes" / "boxes.glb").string(), "--frames", "3", "--warmup",
                                     "1", "--resolution", "128", "--csv", csvFile.string(), "--images",
                                     (root / "images").string(), "--compare-lighting"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("| culled | default | 1200 |"));
    EXPECT_THAT(r.out, HasSubstr("| drawn (culling off) | per pixel only | 1200 |"));
    const CsvTable csv = readCsv(csvFile);
    ASSERT_EQ(csv.size(), 4u);
    const std::pair<const char*, const char*> rows[] = {
        {"on", "default"}, {"on", "per-pixel"}, {"off", "default"}, {"off", "per-pixel"}};
    for (std::size_t i = 0; i < 4; ++i) {
        EXPECT_EQ(csv[i].at("culling"), rows[i].first) << i;
        EXPECT_EQ(csv[i].at("lighting"), rows[i].second) << i;
    }
    for (const CsvRow& row : csv) {
        SCOPED_TRACE(row.at("culling"));
        // The whole hall is in view: every triangle is submitted.
        EXPECT_EQ(row.number("triangles"), 1200.0);
        const double ms = row.number("median_ms");
        EXPECT_GT(ms, 0.0);
        EXPECT_GE(row.number("p90_ms"), ms);
        EXPECT_GT(row.number("cpu_median_ms"), 0.0);
        // Rates at the median (printed with 3 and 2 decimals: a relative tolerance).
        EXPECT_NEAR(row.number("mtriangles_per_s"), 1200.0 / (ms * 1e3), 0.01 + 0.01 * 1200.0 / (ms * 1e3));
        EXPECT_NEAR(row.number("mpixels_per_s"), 128.0 * 128.0 / (ms * 1e3), 0.01 + 0.01 * 16384.0 / (ms * 1e3));
        EXPECT_GT(row.number("vertex_bytes_per_triangle"), 0.0);
        // 3 indices of 4 bytes per triangle.
        EXPECT_DOUBLE_EQ(row.number("index_bytes_per_triangle"), 12.0);
    }
    EXPECT_TRUE(fs::exists(root / "images" / "culled.png"));
    EXPECT_TRUE(fs::exists(root / "images" / "both.png"));
    EXPECT_TRUE(fs::exists(root / "images" / "culled-per-pixel.png"));
    EXPECT_TRUE(fs::exists(root / "images" / "both-per-pixel.png"));
}

TEST(DrawBenchCli, MissingSceneAndBadFlagsAreErrors) {
    const CliResult none = runCavewall({"draw-bench"});
    EXPECT_NE(none.exitCode, 0);
    EXPECT_THAT(none.err, HasSubstr("the scene"));
    const CliResult frames = runCavewall({"draw-bench", "x.glb", "--frames", "0"});
    EXPECT_NE(frames.exitCode, 0);
    EXPECT_THAT(frames.err, HasSubstr("--frames: expected an integer in [1, 100000], got '0'"));
}

}  // namespace
}  // namespace cavewall::test
