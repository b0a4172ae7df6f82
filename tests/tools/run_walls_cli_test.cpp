// `cavewall run`'s walls end to end on a small generated plant (headless): geometry paging,
// baking on demand, the scene's own planning choices and the control (cells without textures).
#include "tests/support/csv_table.h"
#include "tests/support/run_cli.h"
#include "tests/tools/run_cli_support.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// Geometry paging (walls/geometry_pager.h): off by default (zeros); on, the viewer's cell and
// its neighbours are paged in, and a budget smaller than one cell still never drops a frame.
TEST(RunCli, GeometryBudgetPagesCellsAndReportsThem) {
    const fs::path off = outputDir("geometry-off"), on = outputDir("geometry-on");
    ASSERT_EQ(runCavewall(wallRun(off, "sim:walk?seed=2", 12)).exitCode, 0);
    std::vector<std::string> args = wallRun(on, "sim:walk?seed=2", 12);
    args.insert(args.end(), {"--geometry-budget", "0.001", "--sync-paging"});
    const CliResult r = runCavewall(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("run: geometry paging: at most "));
    const auto rowsOff = readCsv(off / "frames.csv"), rowsOn = readCsv(on / "frames.csv");
    ASSERT_EQ(rowsOn.size(), 12u);
    for (const auto& row : rowsOff) EXPECT_EQ(row.at("geometry_page_ins"), "0");
    for (const auto& row : rowsOn) {
        SCOPED_TRACE(row.at("frame"));
        // Whatever is wanted now stays resident over the budget: at least the viewer's cell.
        EXPECT_GT(std::stod(row.at("geometry_resident_mb")), 0.0);
        EXPECT_GE(std::stol(row.at("geometry_page_ins")), 1);
        EXPECT_EQ(row.at("over_alpha"), "0");
    }
}

// Baking on demand from an empty cache: the run starts, reports what it baked, and a second run
// on the same cache misses exactly what the first did not bake. How many textures a run bakes
// depends on this machine's speed; the counts' relations do not.
TEST(RunCli, BakeOnDemandStartsColdAndLeavesItsBakesInTheCache) {
    const fs::path out = outputDir("on-demand"), cache = outputDir("on-demand-cache");
    auto run = [&](const fs::path& folder) {
        std::vector<std::string> args = wallRun(folder, "sim:walk?seed=2", 20);
        args.insert(args.end(), {"--bake-on-demand", "--max-res", "32", "--cache-budget", "100"});
        args[std::find(args.begin(), args.end(), "--cache") - args.begin() + 1] = cache.string();
        return runCavewall(args);
    };
    const std::regex line(
        "baking on demand: (\\d+) textures missing at the start, (\\d+) baked during the run, "
        "(\\d+) still missing; first frame [0-9.]+ s after the scene loaded");
    const CliResult first = run(out);
    ASSERT_EQ(first.exitCode, 0) << first.err;
    std::smatch m1;
    ASSERT_TRUE(std::regex_search(first.out, m1, line)) << first.out;
    const int missing = std::stoi(m1[1]), baked = std::stoi(m1[2]);
    EXPECT_GT(missing, 0);
    const auto rows = readCsv(out / "frames.csv");
    ASSERT_EQ(rows.size(), 20u);
    long previous = 0, handedNow = 0;
    for (const auto& row : rows) {
        SCOPED_TRACE(row.at("frame"));
        const long total = std::stol(row.at("textures_baked"));
        EXPECT_EQ(total - previous, std::stol(row.at("textures_baked_now")));
        EXPECT_LE(total + std::stol(row.at("textures_to_bake")), missing);  // what was handed over, and what is left
        EXPECT_GE(std::stol(row.at("geometry_fallbacks")), 0);
        EXPECT_TRUE(row.at("baker_busy") == "0" || row.at("baker_busy") == "1");
        EXPECT_EQ(row.at("over_alpha"), "0");
        handedNow += std::stol(row.at("textures_baked_now"));
        previous = total;
    }
    EXPECT_LE(handedNow, baked);

    const CliResult second = run(outputDir("on-demand-2"));
    ASSERT_EQ(second.exitCode, 0) << second.err;
    std::smatch m2;
    ASSERT_TRUE(std::regex_search(second.out, m2, line)) << second.out;
    EXPECT_EQ(std::stoi(m2[1]), missing - baked);  // everything the first run baked is in the cache
}

// A scene's own "planning" (as `cavewall walls` writes it) sets the zone size and the texture
// side when the run gives no --min-zone or --max-res; the flags still win. The "walls:" line
// says what the walls were planned and baked with.
TEST(RunCli, PlansWithTheScenesOwnZoneSizeAndTextureSide) {
    const fs::path out = outputDir("scene-planning"), cache = outputDir("scene-planning-cache");
    nlohmann::json plant;
    std::ifstream(smallPlant()) >> plant;
    plant["planning"] = {{"minZone", 3.0}, {"maxRes", 64}};
    const fs::path planned = smallPlant().parent_path() / "planned.json";
    std::ofstream(planned) << plant.dump();
    auto run = [&](const std::vector<std::string>& flags) {
        std::vector<std::string> args = wallRun(out, "sim:walk?seed=2", 1);
        const auto at = [&](const char* flag) { return std::find(args.begin(), args.end(), flag) - args.begin(); };
        args[at("--scene") + 1] = planned.string();
        args[at("--cache") + 1] = cache.string();
        args.erase(args.begin() + at("--min-zone"), args.begin() + at("--min-zone") + 2);  // wallRun's own
        args.push_back("--bake-on-demand");
        args.insert(args.end(), flags.begin(), flags.end());
        return runCavewall(args);
    };
    const CliResult own = run({});
    ASSERT_EQ(own.exitCode, 0) << own.err;
    EXPECT_THAT(own.out, HasSubstr("to bake while walking); zones of at least 3 m, textures of at most 64 texels"));
    const CliResult given = run({"--min-zone", "4", "--max-res", "32"});
    ASSERT_EQ(given.exitCode, 0) << given.err;
    EXPECT_THAT(given.out, HasSubstr("; zones of at least 4 m, textures of at most 32 texels"));
}

TEST(RunCli, BakeOnDemandRefusesBadCombinations) {
    const fs::path out = outputDir("on-demand-bad");
    struct Case {
        std::vector<std::string> extra;
        const char* message;
    };
    const Case cases[] = {
        {{"--bake-on-demand", "--cache-budget", "0"},
         "--cache-budget: expected a disk budget in MB in (0, 1e9], got 0"},
        {{"--bake-on-demand", "--cache-budget", "lots"}, "--cache-budget"},
        {{"--cache-budget", "100"}, "--cache-budget: needs --bake-on-demand"},
        {{"--bake-on-demand", "--sync-paging"}, "--bake-on-demand and --sync-paging: expected one of them, got both"},
    };
    for (const Case& c : cases) {
        SCOPED_TRACE(c.message);
        std::vector<std::string> args = wallRun(out, "sim:walk?seed=2", 2);
        args.insert(args.end(), c.extra.begin(), c.extra.end());
        const CliResult r = runCavewall(args);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_THAT(r.err, HasSubstr(c.message));
    }
}

// --no-textures, the control: the walls' geometry cells frame by frame, nothing baked, loaded or
// drawn on the walls; the same frames as the walls' less their quads. Combinations that would
// draw textures or no walls are refused.
TEST(RunCli, NoTexturesDrawsTheWallsCellsAndNothingOnTheWalls) {
    const fs::path walls = outputDir("control-walls"), control = outputDir("control"),
                   cache = outputDir("control-cache");
    std::vector<std::string> args = wallRun(walls, "sim:walk?seed=2", 12);
    args.push_back("--sync-paging");
    ASSERT_EQ(runCavewall(args).exitCode, 0);
    args = wallRun(control, "sim:walk?seed=2", 12);
    args[std::find(args.begin(), args.end(), "--cache") - args.begin() + 1] = cache.string();  // empty: nothing baked
    args.push_back("--no-textures");
    const CliResult r = runCavewall(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("the control (the walls' cells, no textures)"));
    EXPECT_FALSE(fs::exists(cache) && !fs::is_empty(cache));
    const auto w = readCsv(walls / "frames.csv"), c = readCsv(control / "frames.csv");
    ASSERT_EQ(c.size(), 12u);
    ASSERT_EQ(w.size(), 12u);
    for (std::size_t i = 0; i < c.size(); ++i) {
        SCOPED_TRACE(c[i].at("frame"));
        EXPECT_EQ(c[i].at("cell"), w[i].at("cell"));
        EXPECT_EQ(c[i].at("textures_resident"), "0");
        EXPECT_EQ(c[i].at("max_err_deg"), "0.0000");
        const long quads = std::stol(w[i].at("triangles")) - std::stol(c[i].at("triangles"));
        EXPECT_GE(quads, 0);
        EXPECT_LT(quads, 200);  // two triangles a wall drawn, a view
    }
    for (const char* other : {"--no-walls", "--bake-on-demand", "--clusters"}) {
        std::vector<std::string> bad = wallRun(control, "sim:walk?seed=2", 2);
        bad.insert(bad.end(), {"--no-textures", other});
        const CliResult refused = runCavewall(bad);
        EXPECT_NE(refused.exitCode, 0);
        EXPECT_THAT(refused.err, HasSubstr(std::string("--no-textures and ") + other + ": expected one of them"));
    }
}

}  // namespace
}  // namespace cavewall::test
