// `cavewall bench SCENE --quick` end to end on a small generated plant (headless GL): every mode
// row is present with finite numbers, and bad input gives clear errors. `bench --scale`:
// tests/app/bench/scale_bench_cli_test.cpp.
#include "metrics/image_error.h"
#include "scenes/image_io.h"
#include "tests/support/run_cli.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
namespace fs = std::filesystem;

TEST(BenchSceneCli, QuickRunHasEveryModeWithFiniteNumbers) {
    const test::TempFolder root("bench_cli_quick");
    const fs::path plant = root / "plant20k";
    // Generated every run: a scene left by an earlier build may come from an older generator.
    const CliResult g = runCavewall({"generate", "plant", "--triangles", "20000", "--out", plant.string()});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const fs::path out = root / "out";
    fs::remove_all(out);
    const CliResult r =
        runCavewall({"bench", (plant / "scene.json").string(), "--quick", "--mono", "--frames", "12", "--out",
                     out.string(), "--cache", (root / "cache").string(), "--alphas", "20,30", "--warp-alpha", "30",
                     "--clusters", "--cluster-budgets", "0.5,200", "--save-worst"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("| 1 | full |"));
    // --quick keeps its small images, and says so in the header and on every figure line.
    EXPECT_THAT(r.out, HasSubstr("4 screens at 128x128 pixels, mono stereo mode"));
    // The quick path is walked at about 1000 m/s: a warp-morph spans its half metre in 0.5 ms.
    EXPECT_THAT(r.out, HasSubstr("a warp-morph lasts 0.000"));
    EXPECT_THAT(r.out,
                HasSubstr(" s of the path's time, the stretch a viewer walks at 1 m/s in `cavewall run`'s 0.5 s"));
    EXPECT_THAT(r.out, HasSubstr("portal culling: on (walls modes and the control: each view draws other cells'"));
    // Full geometry, the walls modes (but the paged one), the clusters (--clusters, held to
    // 60 Hz by the controller), the control and the limit with levels of detail are timed in
    // the same seconds.
    EXPECT_THAT(r.out,
                HasSubstr("drawn frame by frame in turn (the same seconds): full, full lod 1px, walls flat a=20 blend, "
                          "walls flat a=30 blend, walls flat a=20 blend lod 1px"));
    EXPECT_THAT(r.out,
                HasSubstr("walls flat a=30 blend lod 1px frame 16.7ms, clusters frame 0.5ms, clusters frame 200ms, "
                          "cells lod 1px, near lod 1px, frame by frame in turn"));
    // Before the run the console says where the triangle budgets will come from; the report's
    // line names the budgets the warm-up chose, as the table does.
    EXPECT_THAT(r.out, HasSubstr("walls flat a=20 blend lod 1px budget (the median triangles of the same mode "
                                 "without one, after its warm-up), walls flat a=30 blend lod 1px budget ("));
    const std::size_t drawn = r.out.find("drawn frame by frame in turn (the same seconds): ");
    ASSERT_NE(drawn, std::string::npos);
    EXPECT_THAT(r.out.substr(drawn, r.out.find('\n', drawn) - drawn),
                ::testing::ContainsRegex("walls flat a=20 blend lod 1px budget [0-9]+, walls flat a=30 blend lod 1px "
                                         "budget [0-9]+, "));
    // One clusters mode per --cluster-budgets entry, each with its budget line: no frame at
    // 128x128 takes as little as 0.5 ms (infeasible, said so with the floor), and 200 ms is
    // more than any takes (feasible: the line goes straight on to the floor).
    EXPECT_THAT(r.out, HasSubstr("figures (128x128 per screen, mono): clusters frame 0.5ms: p50 "));
    EXPECT_THAT(r.out, HasSubstr("x the budget (infeasible: the floor is above the budget); floor (the cheapest "
                                 "selection's frame time, median) "));
    EXPECT_THAT(r.out, HasSubstr("figures (128x128 per screen, mono): clusters frame 200ms: p50 "));
    EXPECT_THAT(r.out, HasSubstr("x the budget; floor"));
    EXPECT_THAT(r.out, HasSubstr("clusters' measured frame ms against their predicted cost over 24 frames"));
    EXPECT_THAT(r.out, HasSubstr("bench: noise floor, walls flat a=30 blend lod 1px frame 16.7ms interleaved"));
    // The recommended walls mode, by the rule of app/bench/recommend.h, on the console and in
    // bench.md (which mode depends on the run's times).
    EXPECT_THAT(r.out, testing::ContainsRegex("- recommended: (walls flat a=[23]0 [^(]*\\(#[0-9]+; |none \\()"));
    EXPECT_THAT(readFile(out / "bench.md"), HasSubstr("- recommended: "));
    // The bound holds in every walls mode (frame by frame, also in bench_frames.csv).
    EXPECT_THAT(r.out, HasSubstr("figures (128x128 per screen, mono): textures drawn over alpha in"));
    EXPECT_THAT(r.out, HasSubstr("walls modes: 0\n"));
    // --alphas 20,30: no mode is at alpha <= 10, and the line says so.
    EXPECT_THAT(r.out, HasSubstr("figures (128x128 per screen, mono): no walls mode at alpha <= 10"));
    EXPECT_THAT(r.out, HasSubstr("figures (128x128 per screen, mono): the limit (near geometry and bare wall quads)"));
    // Figures only: targets are judged in the docs, not by the report.
    EXPECT_THAT(r.out, Not(HasSubstr("targets")));
    EXPECT_THAT(r.out, Not(HasSubstr("met)")));
    EXPECT_THAT(r.out, Not(HasSubstr("not met")));
    const test::CsvTable csv = test::readCsv(out / "bench.csv");
    std::map<std::string, int> rows;
    for (const test::CsvRow& row : csv) {
        const std::string mode = row.at("mode");
        const bool lod = row.number("lod_px") > 0.0;
        const bool budget = row.number("triangle_budget") > 0.0;
        const bool frame = row.number("frame_budget_ms") > 0.0;
        const std::string key = mode + (mode == "walls" ? " " + row.at("alpha_deg") + " " + row.at("transition") : "") +
                                (lod ? " lod" : "") + (budget ? " budget" : "") + (frame ? " frame" : "");
        ++rows[key];
        SCOPED_TRACE(key);
        for (const std::string& name : csv.columns) {
            if (name == "mode" || name == "alpha_deg" || name == "transition" || name == "scene" || name == "wall_kind")
                continue;
            const double v = row.number(name);
            // The reference's PSNRs against itself (and so its gain over the control) are
            // +infinity; every other number is finite. Only a gain over the control may be negative.
            const bool psnr = name == "psnr_db" || name == "worst_frame_psnr_db" || name == "p5_frame_psnr_db" ||
                              name == "psnr_gain_db";
            const bool stereo = name == "stereo_mean_arcmin" || name == "stereo_beyond_share";
            if (stereo) {  // a mono display: not measured
                EXPECT_TRUE(std::isnan(v)) << name;
                continue;
            }
            if (psnr && mode == "full" && !lod)
                EXPECT_TRUE(std::isinf(v) && v > 0) << name;
            else
                EXPECT_TRUE(std::isfinite(v)) << name << " = " << row.at(name);
            if (name != "psnr_gain_db") {
                EXPECT_GE(v, 0.0) << name;
            }
        }
        EXPECT_LE(row.number("flip_share_over_0.1"), 1.0);
        EXPECT_GE(row.number("psnr_db"), row.number("worst_frame_psnr_db"));  // pooled: never below the worst
        if (mode == "cells" || mode == "cells+layer") {  // the control against itself; the layer has weight 0
            EXPECT_EQ(row.number("psnr_gain_db"), 0.0);
            EXPECT_EQ(row.number("flip_ratio"), 1.0);
        }
        if (mode == "walls" || mode == "cells" || mode == "near") {
            EXPECT_GT(row.number("flip_mean"), 0.0);
        }
        EXPECT_GT(row.number("frame_ms_p50"), 0.0);
        if (mode == "walls") {
            EXPECT_GT(row.number("textures"), 0.0);
        }
        EXPECT_EQ(row.number("over_alpha"), 0.0);
        // Paged from a cold start, textures arrive during the timed frames; every other mode
        // made them resident before (and modes without walls have none).
        if (key == "walls 30 blend paged")
            EXPECT_GT(row.number("uploaded_mb_mean"), 0.0);
        else
            EXPECT_EQ(row.number("uploaded_mb_p99"), 0.0);
    }
    // With levels of detail (--lod defaults to 1 px): full, the control, near and every blend
    // mode again, every blend mode with them under a triangle budget, and every blend mode with
    // them held to 60 Hz by the frame-time controller.
    const std::map<std::string, int> expected = {{"full", 1},
                                                 {"full lod", 1},
                                                 {"cells", 1},
                                                 {"cells+layer", 1},
                                                 {"near", 1},
                                                 {"cells lod", 1},
                                                 {"near lod", 1},
                                                 {"walls 20 blend", 1},
                                                 {"walls 30 blend", 1},
                                                 {"walls 20 blend lod", 1},
                                                 {"walls 30 blend lod", 1},
                                                 {"walls 30 warp", 1},
                                                 {"walls 30 blend paged", 1},
                                                 {"walls 20 blend lod budget", 1},
                                                 {"walls 30 blend lod budget", 1},
                                                 {"walls 20 blend lod frame", 1},
                                                 {"walls 30 blend lod frame", 1},
                                                 {"clusters frame", 2}};
    EXPECT_EQ(rows, expected);
    EXPECT_TRUE(fs::is_regular_file(out / "bench.png"));
    EXPECT_TRUE(fs::is_regular_file(out / "bench.md"));
    // Per screen: every mode times and counts each of cave4's four screens.
    const test::CsvTable screens = test::readCsv(out / "bench_screens.csv");
    for (const test::CsvRow& row : screens) {
        EXPECT_GT(row.number("cpu_ms_p50"), 0.0) << row.at("screen");  // every screen was drawn
        EXPECT_TRUE(std::isfinite(row.number("triangles"))) << row.at("screen");
    }
    for (const test::CsvRow& row : screens)
        for (const char* name :
             {"flip_mean", "flip_share_over_0.1", "popping_peak", "popping_rms", "capped_mean_psnr_db"})
            EXPECT_TRUE(std::isfinite(row.number(name))) << row.at("screen") << " " << name;
    const std::size_t screenRows = screens.size();
    EXPECT_EQ(screenRows, 19u * 4);
    // A FLIP map of the worst image of every mode but the reference (mode 1), and with
    // --save-worst the two images it compares.
    EXPECT_FALSE(fs::exists(out / "flip_worst_1.png"));
    EXPECT_FALSE(fs::exists(out / "worst_1.png"));
    for (int mode = 2; mode <= 19; ++mode)
        for (const std::string name : {"flip_worst_", "worst_"})
            EXPECT_TRUE(fs::is_regular_file(out / (name + std::to_string(mode) + ".png"))) << name << mode;
    // The control's (mode 3) saved pair has the PSNR that bench_compared.csv lists for the image
    // bench.md names as its worst.
    std::smatch worst;
    const std::string md = readFile(out / "bench.md");
    ASSERT_TRUE(std::regex_search(md, worst,
                                  std::regex("flip_worst_3.png: cells, frame ([0-9]+), screen ([a-z]+), eye "
                                             "([0-9]+), FLIP mean")));
    std::optional<double> listed;
    for (const test::CsvRow& row : test::readCsv(out / "bench_compared.csv"))
        if (row.at("mode") == "cells" && row.at("frame") == worst[1] && row.at("screen") == worst[2] &&
            row.at("eye") == worst[3])
            listed = row.number("psnr_db");
    ASSERT_TRUE(listed.has_value());
    const double saved =
        metrics::squaredError(scenes::readImage(out / "worst_3.png"), scenes::readImage(out / "worst_3_full.png"))
            .psnrDb();
    EXPECT_GT(saved, 5.0);  // the cells leave geometry out: the images differ
    EXPECT_NEAR(saved, *listed, 1e-3 * *listed);
}

// In stereo (--stereo separate) both eyes are drawn and compared, and every mode's stereo
// error is measured from the depth read back for each eye: zero for the reference, finite and
// non-zero where a mode leaves cells out or puts them on the walls. With --walls flat,depth the
// flat walls are drawn in turn with the depth walls, each kind from its own bake, and show
// everything behind them at the wall's depth: many times the depth walls' stereo error.
TEST(BenchSceneCli, StereoRunMeasuresTheStereoErrorPerEye) {
    const test::TempFolder root("bench_cli_stereo");
    const fs::path plant = root / "plant20k";
    const CliResult g = runCavewall({"generate", "plant", "--triangles", "20000", "--out", plant.string()});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const fs::path out = root / "out";
    const CliResult r = runCavewall({"bench",
                                     (plant / "scene.json").string(),
                                     "--quick",
                                     "--frames",
                                     "6",
                                     "--stereo",
                                     "separate",
                                     "--lod",
                                     "0",
                                     "--frame-budget-ms",
                                     "0",
                                     "--alphas",
                                     "20",
                                     "--warp-alpha",
                                     "20",
                                     "--walls",
                                     "flat,depth",
                                     "--out",
                                     out.string(),
                                     "--cache",
                                     (root / "cache").string(),
                                     "--no-portal-culling"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("portal culling: off (--no-portal-culling: neighbours drawn as geometry are drawn "
                                 "whole)"));
    EXPECT_THAT(r.out, HasSubstr("drawn frame by frame in turn (the same seconds): full, walls depth a=20 blend, "
                                 "walls flat a=20 blend, walls depth a=20 warp;"));
    EXPECT_THAT(r.out, HasSubstr("bake flat walls a=20: "));
    EXPECT_THAT(r.out, HasSubstr("bake depth walls a=20: "));
    EXPECT_THAT(r.out, HasSubstr("4 screens at 128x128 pixels, separate stereo mode"));
    EXPECT_THAT(r.out, HasSubstr("stereo: both eyes drawn, every image metric computed per output image (per eye in "
                                 "separate mode); stereo error"));
    EXPECT_THAT(r.out, HasSubstr("figures (128x128 per screen, separate)"));
    const test::CsvTable csv = test::readCsv(out / "bench.csv");
    ASSERT_EQ(csv.size(), 8u);                  // full, cells, cells+layer, near, depth blend, flat blend, warp, paged
    std::map<std::string, double> blendStereo;  // by kind
    for (const test::CsvRow& row : csv) {
        if (row.at("mode") == "walls" && row.at("transition") == "blend")
            blendStereo[row.at("wall_kind")] = row.number("stereo_mean_arcmin");
        SCOPED_TRACE(row.at("mode") + " " + row.at("transition"));
        const double mean = row.number("stereo_mean_arcmin"), share = row.number("stereo_beyond_share");
        if (row.at("mode") == "full") {  // the reference against itself: nothing compared, no error
            EXPECT_EQ(mean, 0.0);
            continue;
        }
        EXPECT_TRUE(std::isfinite(mean) && mean > 0.0) << mean;
        EXPECT_TRUE(share >= 0.0 && share <= 1.0) << share;
    }
    ASSERT_EQ(blendStereo.size(), 2u);
    EXPECT_GT(blendStereo.at("flat"), 3.0 * blendStereo.at("depth"));
    // Walls with every texture resident never fall back; the paged mode may, to geometry or to
    // the textures it drew last (bench_frames.csv counts both per frame).
    for (const test::CsvRow& f : test::readCsv(out / "bench_frames.csv")) {
        SCOPED_TRACE(f.at("mode") + " frame " + f.at("frame"));
        const double kept = f.number("kept_fallbacks"), geometry = f.number("geometry_fallbacks");
        EXPECT_TRUE(kept >= 0.0 && geometry >= 0.0);
        if (f.at("mode").find("paged") == std::string::npos) {
            EXPECT_EQ(kept + geometry, 0.0);
        }
    }
    for (const test::CsvRow& row : test::readCsv(out / "bench_screens.csv"))
        EXPECT_TRUE(std::isfinite(row.number("stereo_mean_arcmin"))) << row.at("screen");
}

// Automatic walls and baking on demand end to end on the small plant: `walls --keep-paths`
// proposes other cells and walls for it (its walk path kept), `bench --compare-scene` draws
// them beside the generator's walls in the same seconds, and `--on-demand` walks from an empty
// private cache while the background baker bakes; the shared cache gets the two scenes' bakes
// only.
TEST(BenchSceneCli, ComparesAnotherSceneAndBakesOnDemandFromAnEmptyCache) {
    const test::TempFolder root("bench_cli_compare");
    const fs::path plant = root / "plant20k";
    const CliResult g = runCavewall({"generate", "plant", "--triangles", "20000", "--out", plant.string()});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const fs::path automatic = root / "auto" / "scene.json";
    fs::create_directories(automatic.parent_path());
    const CliResult w =
        runCavewall({"walls", (plant / "scene.json").string(), "--out", automatic.string(), "--keep-paths", "--max-res",
                     "128", "--max-cells", "3", "--min-cell", "8", "--alpha", "30", "--ms-per-wall",
                     "0"});  // free wall layers: 20 k triangles still pay for cells
    ASSERT_EQ(w.exitCode, 0) << w.out << w.err;
    const fs::path out = root / "out", cache = root / "cache";
    fs::remove_all(out);
    fs::remove_all(cache);
    const CliResult r = runCavewall({"bench",
                                     "--mono",
                                     (plant / "scene.json").string(),
                                     "--quick",
                                     "--frames",
                                     "12",
                                     "--out",
                                     out.string(),
                                     "--cache",
                                     cache.string(),
                                     "--alphas",
                                     "30",
                                     "--warp-alpha",
                                     "30",
                                     "--lod",
                                     "0",
                                     "--frame-budget-ms",
                                     "0",
                                     "--compare-scene",
                                     automatic.string(),
                                     "--on-demand"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    // The compare scene's walls are drawn frame by frame in turn with full geometry and the
    // plant's own, on the plant's eye path.
    EXPECT_THAT(
        r.out,
        HasSubstr("drawn frame by frame in turn (the same seconds): full, walls flat a=30 blend, walls flat a=30 "
                  "warp, walls flat a=30 blend [auto]"));
    EXPECT_THAT(r.out, HasSubstr("compare scene [auto]: " + automatic.string()));
    EXPECT_THAT(
        r.out,
        HasSubstr("figures (128x128 per screen, mono): walls flat a=30 blend [auto] against walls flat a=30 blend: "
                  "speed-up"));
    EXPECT_THAT(r.out,
                HasSubstr("figures (128x128 per screen, mono): walls flat a=30 blend on demand from an empty cache: "
                          "first frame"));
    EXPECT_THAT(r.out, Not(HasSubstr("met)")));
    EXPECT_THAT(r.out, Not(HasSubstr("not met")));
    const test::CsvTable csv = test::readCsv(out / "bench.csv");
    std::map<std::string, int> rows;
    for (const test::CsvRow& row : csv) ++rows[row.at("mode") + " " + row.at("transition") + " " + row.at("scene")];
    const std::map<std::string, int> expected = {{"full none bench", 1},         {"cells none bench", 1},
                                                 {"cells+layer none bench", 1},  {"near none bench", 1},
                                                 {"walls blend bench", 1},       {"walls warp bench", 1},
                                                 {"walls blend paged bench", 1}, {"walls blend on demand bench", 1},
                                                 {"walls blend auto", 1}};
    EXPECT_EQ(rows, expected);
    for (const test::CsvRow& row : csv) {
        SCOPED_TRACE(row.at("mode") + " " + row.at("transition") + " " + row.at("scene"));
        EXPECT_EQ(row.number("over_alpha"), 0.0);
        if (row.at("transition") == "blend on demand") {
            EXPECT_GT(row.number("first_frame_s"), 0.0);
            EXPECT_GT(row.number("textures"), 0.0);
            EXPECT_LE(row.number("textures_baked"), row.number("textures"));
            EXPECT_LE(row.number("fallbacks_until_frame"), 12.0);
            EXPECT_LE(row.number("fallback_frames"), row.number("fallbacks_until_frame"));
            EXPECT_TRUE(std::isfinite(row.number("psnr_db")));
        } else {
            EXPECT_EQ(row.number("first_frame_s"), 0.0);
            EXPECT_EQ(row.number("textures_baked"), 0.0);
        }
        if (row.at("scene") == "auto") {
            EXPECT_GT(row.number("speedup"), 0.0);
        }
    }
    // bench_frames.csv: per frame, the on-demand mode's fallbacks (summing to bench.csv's) and
    // its running total of textures baked, which never falls.
    const test::CsvTable frames = test::readCsv(out / "bench_frames.csv");
    double fallbacks = 0.0, baked = 0.0;
    int onDemandFrames = 0;
    for (const test::CsvRow& f : frames) {
        if (f.at("mode") != "walls flat a=30 blend on demand") continue;
        ++onDemandFrames;
        fallbacks += f.number("geometry_fallbacks");
        EXPECT_GE(f.number("textures_baked"), baked);
        baked = f.number("textures_baked");
    }
    EXPECT_EQ(onDemandFrames, 12);
    for (const test::CsvRow& row : csv)
        if (row.at("transition") == "blend on demand") {
            EXPECT_EQ(row.number("geometry_fallbacks"), fallbacks);
        }
    // The on-demand bake went into the private cache (one bake folder beside the marker), the
    // two scenes' bakes into the shared one.
    auto folders = [](const fs::path& dir) {
        int n = 0;
        for (const auto& e : fs::directory_iterator(dir)) n += e.is_directory();
        return n;
    };
    EXPECT_TRUE(fs::exists(out / "on-demand-cache" / ".cavewall-on-demand-cache"));
    EXPECT_EQ(folders(out / "on-demand-cache"), 1);
    EXPECT_EQ(folders(cache), 2);
    // The walk path is the plant's: `walls --keep-paths` kept it.
    auto walkPath = [](const fs::path& file) {
        std::ifstream in(file);
        return nlohmann::json::parse(in).at("walkPath");
    };
    EXPECT_FALSE(walkPath(plant / "scene.json").empty());
    EXPECT_EQ(walkPath(plant / "scene.json"), walkPath(automatic));
}

// Bad --compare-scene and --on-demand input fails before anything is baked.
TEST(BenchSceneCli, BadCompareSceneOrOnDemandCacheIsAClearError) {
    const test::TempFolder root("bench_cli_compare_bad");
    const fs::path plant = root / "plant20k", house = root / "house";
    ASSERT_EQ(runCavewall({"generate", "plant", "--triangles", "20000", "--out", plant.string()}).exitCode, 0);
    ASSERT_EQ(runCavewall({"generate", "house", "--triangles", "2000", "--out", house.string()}).exitCode, 0);
    const fs::path out = root / "out";
    const std::string scene = (plant / "scene.json").string();
    struct Case {
        std::vector<std::string> args;
        std::string message;
    };
    const Case cases[] = {
        {{"bench", scene, "--quick", "--compare-scene", (house / "scene.json").string()},
         "--compare-scene " + (house / "scene.json").string() + ": expected the same model as " + scene + " ("},
        {{"bench", scene, "--quick", "--compare-scene", (root / "none.json").string()}, "none.json"},
        {{"bench", scene, "--quick", "--compare-scene", scene + "," + scene},
         "--compare-scene: expected scenes whose labels differ, got 'plant20k' for"},
        {{"bench", scene, "--quick", "--compare-scene", scene + ","},
         "--compare-scene: expected scene files separated by commas, got an empty entry 2"},
        {{"bench", scene, "--quick", "--on-demand", "--walls", "depth"},
         "--on-demand: baking on demand draws flat walls only, got --walls depth"},
        {{"bench", scene, "--quick", "--on-demand", "--out", out.string(), "--cache",
          (out / "on-demand-cache").string()},
         "expected a folder apart from the shared bake cache"},
        {{"bench", scene, "--quick", "--on-demand", "--out", root.path().string(), "--cache",
          (root / "cache").string()},
         "got a folder with other files; not deleting it"},  // root/on-demand-cache holds a stray file
    };
    fs::create_directories(root / "on-demand-cache");
    std::ofstream(root / "on-demand-cache" / "mine.txt") << "keep";
    for (const Case& c : cases) {
        SCOPED_TRACE(c.message);
        const CliResult r = runCavewall(c.args);
        EXPECT_NE(r.exitCode, 0);
        EXPECT_THAT(r.err, HasSubstr(c.message));
        EXPECT_THAT(r.out, ::testing::Not(HasSubstr("bench: plan and bake")));  // nothing baked first
    }
    EXPECT_TRUE(fs::exists(root / "on-demand-cache" / "mine.txt"));
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
        {{"bench", (test::testOutputRoot() / "bench_cli_missing" / "scene.json").string(), "--quick"}, "missing"},
        {{"bench", "x.json", "--stereo", "quad-buffer"}, "--stereo: expected mono or separate, got 'quad-buffer'"},
        {{"bench", "x.json", "--walls", "depth,flat"},
         "bench: --walls: expected flat, depth or flat,depth (flat walls beside depth walls), got 'depth,flat'"},
        {{"bench", "x.json", "--cluster-budgets", "40"}, "bench: --cluster-budgets needs --clusters"},
        {{"bench", "x.json", "--clusters", "--cluster-budgets", "40,0"},
         "bench: --cluster-budgets: expected milliseconds in (0, 100000], got 0"},
        {{"bench", "x.json", "--clusters", "--cluster-budgets", "40,x"}, "--cluster-budgets"},
        // The new names (the old ones above are kept for one release); messages name what was typed.
        {{"bench", "x.json", "--hierarchy-budgets", "40"}, "bench: --hierarchy-budgets needs --hierarchy"},
        {{"bench", "x.json", "--hierarchy", "--hierarchy-budgets", "40,0"},
         "bench: --hierarchy-budgets: expected milliseconds in (0, 100000], got 0"},
        {{"bench", "x.json", "--hierarchy", "--clusters"},
         "--hierarchy and --clusters: expected one of them, got both"},
        {{"bench", "x.json", "--portal-culling", "--no-portal-culling"},
         "--portal-culling and --no-portal-culling: expected one of them, got both"},
        {{"bench", "--scale", "2M,x"}, "--scale: entry 2 'x': expected a triangle count"},
        // A stray word is refused, not ignored.
        {{"bench", "plant.glb", "--scale", "2M"},
         "bench --scale: unexpected word 'plant.glb' (the scale bench walks the plants it generates"},
        {{"bench", "x.json", "y.json"}, "bench: unexpected word 'y.json' (expected one SCENE, then --flags)"},
        {{"bench", "--scale", "2M", "--scale-metres", "0"}, "--scale-metres"},
        {{"bench", "--scale", "2M", "--lod", "0"}, "--triangle-budget: needs levels of detail (--lod PX with PX > 0)"},
        {{"bench", "--scale", "2M", "--triangle-budget", "lots"}, "--triangle-budget"},
        {{"bench", "--scale", "2M", "--walls", "curved"},
         "--walls: expected flat, depth or flat,depth (both kinds in one run), got 'curved'"},
        {{"bench", "--scale", "2M", "--walls", "depth,flat"}, "--walls: expected flat, depth or flat,depth"},
        // The scene bench's own flags are refused with --scale, not ignored.
        {{"bench", "--scale", "2M", "--save-worst"},
         "bench --scale: --save-worst is a flag of `bench SCENE` only (see cavewall bench --help), got it with "
         "--scale"},
        {{"bench", "--scale", "2M", "--alphas", "10"}, "bench --scale: --alphas is a flag of `bench SCENE` only"},
        {{"bench", "--scale", "2M", "--stereo", "sideways"},
         "bench: --stereo: expected mono or separate, got 'sideways'"},
        {{"bench", "--scale", "2M", "--min-zone", "0.25"},
         "bench --scale: plan options: minZoneSize: expected more than twice blendWidth (0.4 m), got 0.25 m"},
        // An empty path is refused, not replaced by the default folder.
        {{"bench", "x.json", "--cache", ""}, "--cache: expected a path, got an empty word"},
        {{"bench", "--scale", "2M", "--data", ""}, "--data: expected a path, got an empty word"},
        // Sizes the generator cannot make are refused up front, naming the limit.
        {{"bench", "--scale", "129M"},
         "bench: --scale: entry 1 '129M': expected at most 128000000 triangles (128M, the largest plant the "
         "generator makes), got 129000000"},
        {{"bench", "--scale", "1k,1000M"}, "bench: --scale: entry 2 '1000M': expected at most 128000000 triangles"},
        {{"bench", "--scale", "2147483647"}, "bench: --scale: entry 1 '2147483647': expected at most 128000000"},
        {{"bench", "--scale", "0x400"},
         "bench: --scale: entry 1 '0x400': expected a triangle count such as 2M, 500k or 8000000 (decimal digits, "
         "then k or M; at least 1)"},
        // --stability is a bench of its own.
        {{"bench", "--stability", "--scale", "2M"},
         "bench: --stability runs alone (expected no other flags or words, got --scale)"},
        {{"bench", "x.json", "--stability"},
         "bench: --stability runs alone (expected no other flags or words, got 'x.json')"},
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
