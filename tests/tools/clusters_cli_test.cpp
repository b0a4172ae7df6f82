// Maciel & Shirley's (1995) textured clusters through `cavewall run --clusters` end to end, on
// the small plant of run_cli_support.h.
#include "scenes/image_io.h"
#include "tests/tools/run_cli_support.h"
#include "tests/support/csv_table.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// Textured clusters end to end: `run --clusters` on the small plant's scene.json and on its
// bare GLB. Every frame's selection stays within its budget of predicted milliseconds and draws
// something; a second run, with the new flag names (`--hierarchy*`; `--clusters*` are their old
// names), finds every cluster in the cache.
enum class FlagNames { Old, New };

std::vector<std::string> clusterRun(const fs::path& scene, const fs::path& out, const std::string& cache,
                                    FlagNames names = FlagNames::Old) {
    const bool old = names == FlagNames::Old;
    return {"run",
            "--scene",
            scene.string(),
            "--display",
            testDisplay(),
            "--tracker",
            "sim:walk?seed=2",
            "--frames",
            "8",
            old ? "--clusters" : "--hierarchy",
            old ? "--cluster-divisions" : "--hierarchy-divisions",
            "4",
            old ? "--cluster-res" : "--hierarchy-res",
            "16",
            "--cache",
            cache,
            "--out",
            out.string()};
}

// "run: clusters: N (...": the clusters of the hierarchy (one per node of the tree).
std::string clusterCount(const std::string& out) {
    const std::size_t at = out.find("run: clusters: ");
    return at == std::string::npos ? std::string() : out.substr(at, out.find(' ', at + 15) - at);
}

// Within the budget, unless the budget is below the least a frame can cost: then the root
// cluster alone (one box) is drawn, as Maciel & Shirley's traversal starts from it. (A frame
// with cross-fades under way also pays for what they keep drawing, so it is checked only for
// drawing something.)
void expectWithinBudget(const CsvTable& rows) {
    for (const auto& row : rows) {
        SCOPED_TRACE(row.at("frame"));
        if (row.number("cluster_fades") == 0.0 &&
            row.number("cluster_predicted_ms") > row.number("cluster_budget_ms") + 1e-3) {
            EXPECT_EQ(row.number("cluster_objects"), 0.0);
            EXPECT_EQ(row.number("cluster_textured") + row.number("cluster_average"), 1.0);
        }
        EXPECT_GE(row.number("cluster_budget_ms"), 0.0);
        // The selection's own cost never exceeds its budget, or the cheapest selection's.
        EXPECT_LE(row.number("cluster_selected_ms"),
                  std::max(row.number("cluster_budget_ms"), row.number("cluster_cheapest_ms")) + 1e-3);
        EXPECT_GT(row.number("cluster_objects") + row.number("cluster_textured") + row.number("cluster_average"), 0.0);
    }
}

TEST(RunCli, ClustersDrawTheSelectionWithinTheBudgetAndReuseTheirImpostors) {
    const std::string cache = (fs::path(cacheDir()).parent_path() / "cluster-cache").string();
    fs::remove_all(cache);
    const fs::path first = outputDir("clusters-first"), second = outputDir("clusters-second");
    std::vector<std::string> firstArgs = clusterRun(smallPlant(), first, cache);
    firstArgs.insert(firstArgs.end(), {"--save-frames", "every:4"});
    CliResult r = runCavewall(firstArgs);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    // The top view of what frame 4 drew, beside its screens' images.
    const scenes::Image diagram = scenes::readImage(first / "frames" / "00004" / "clusters.png");
    EXPECT_EQ(diagram.width, 640);
    EXPECT_THAT(r.out, HasSubstr("run: clusters: "));
    EXPECT_THAT(r.out, HasSubstr(", 0 from the cache)"));
    const auto rows = readCsv(first / "frames.csv");
    ASSERT_EQ(rows.size(), 8u);
    expectWithinBudget(rows);
    // 16.7 ms of predicted cost: the default budget without a frame-time controller.
    EXPECT_NEAR(rows[0].number("cluster_budget_ms"), 16.6667, 1e-3);
    // The walk refines clusters on its way: those switches are cross-faded (8 frames by default).
    double fades = 0.0;
    for (const auto& row : rows) fades = std::max(fades, row.number("cluster_fades"));
    EXPECT_GT(fades, 0.0);
    const std::string firstCount = clusterCount(r.out);
    // The new names give the same hierarchy: as many clusters, the same impostors (their cache
    // keys hold the divisions and the resolution), the same frames.
    r = runCavewall(clusterRun(smallPlant(), second, cache, FlagNames::New));
    ASSERT_EQ(r.exitCode, 0) << r.err;
    EXPECT_THAT(r.out, HasSubstr("(0 made, "));
    EXPECT_EQ(clusterCount(r.out), firstCount);
    EXPECT_FALSE(firstCount.empty());
    const auto secondRows = readCsv(second / "frames.csv");
    ASSERT_EQ(secondRows.size(), rows.size());
    expectWithinBudget(secondRows);
    EXPECT_NEAR(secondRows[0].number("cluster_budget_ms"), rows[0].number("cluster_budget_ms"), 1e-9);
    // A tight budget of 0.5 ms draws clusters as boxes; the controller then sets each budget
    // (frames here take more than 0.5 ms whatever is drawn, so it stays at the root alone), and
    // every frame after the first reports the target as infeasible: its floor (the cheapest
    // selection's frame time) is above it.
    const fs::path tight = outputDir("clusters-tight");
    std::vector<std::string> args = clusterRun(smallPlant(), tight, cache, FlagNames::New);
    args.insert(args.end(), {"--frame-budget-ms", "0.5", "--hierarchy-fade", "0"});
    r = runCavewall(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto tightRows = readCsv(tight / "frames.csv");
    expectWithinBudget(tightRows);
    for (const auto& row : tightRows) EXPECT_EQ(row.number("cluster_fades"), 0.0);  // switched off
    for (std::size_t i = 0; i < tightRows.size(); ++i) {
        SCOPED_TRACE(i);
        EXPECT_NEAR(tightRows[i].number("cluster_target_ms"), 0.5, 1e-9);
        EXPECT_NEAR(tightRows[i].number("cluster_selected_ms"), tightRows[i].number("cluster_cheapest_ms"), 1e-3);
        if (i == 0) continue;  // the controller has seen no frame yet
        EXPECT_GT(tightRows[i].number("cluster_floor_ms"), 0.5);
        EXPECT_GT(tightRows[i].number("cluster_predicted_frame_ms"), 0.0);
    }
    EXPECT_GT(tightRows[0].number("cluster_textured") + tightRows[0].number("cluster_average"), 0.0);
}

TEST(RunCli, ClustersRunOnABareGlb) {
    const std::string cache = (fs::path(cacheDir()).parent_path() / "cluster-cache-glb").string();
    const fs::path out = outputDir("clusters-glb");
    std::vector<std::string> args = clusterRun(smallPlant().parent_path() / "plant.glb", out, cache);
    args.insert(args.end(), {"--cluster-fade", "0"});  // the old name of --hierarchy-fade
    const CliResult r = runCavewall(args);
    ASSERT_EQ(r.exitCode, 0) << r.err;
    const auto rows = readCsv(out / "frames.csv");
    expectWithinBudget(rows);
    for (const auto& row : rows) EXPECT_EQ(row.number("cluster_fades"), 0.0);  // switched off
}

TEST(RunCli, ClustersRefuseATriangleBudget) {
    std::vector<std::string> args = clusterRun(smallPlant(), outputDir("clusters-bad"), cacheDir());
    args.insert(args.end(), {"--lod", "1", "--triangle-budget", "1000"});
    const CliResult r = runCavewall(args);
    EXPECT_NE(r.exitCode, 0);
    EXPECT_THAT(r.err, HasSubstr("--clusters and --triangle-budget"));
}

}  // namespace
}  // namespace cavewall::test
