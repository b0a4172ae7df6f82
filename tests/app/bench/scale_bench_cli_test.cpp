// `cavewall bench --scale` end to end on tiny generated plants (headless GL): the modes per
// size, depth walls, a plant folder holding another model, and data folders that cannot be
// written.
#include "tests/support/run_cli.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <sys/wait.h>
#include <vector>

namespace cavewall::test {
namespace {

using ::testing::HasSubstr;
namespace fs = std::filesystem;

// `bench --scale` end to end on two tiny sizes (both below 2 M triangles: the same 80 m plant,
// generated into a folder each): six modes per size (full geometry with levels of detail the
// alternative a user would pick), the walls' paged geometry no more than
// the whole model (shared meshes stored once), only the requested textures baked, the second
// size's bake found in the scale cache (the same scene bytes, plan and settings), and the
// budgeted walls drawing no more triangles than the walls under the near limit's median.

// A tiny scale run's arguments into `root` (data and out folders of its own) at `sizes`: 32 x 32
// screens, 4 frames over 10 m, 16-texel bakes, images compared every 2 frames, in the display's
// own stereo mode (cave4: separate).
std::vector<std::string> tinyScaleArgs(const fs::path& root, const std::string& sizes) {
    fs::remove_all(root / "data");
    return {"bench",
            "--scale",
            sizes,
            "--resolution",
            "32",
            "--frames",
            "4",
            "--bake-resolution",
            "16",
            "--scale-metres",
            "10",
            "--compare-every",
            "2",
            "--data",
            (root / "data").string(),
            "--out",
            (root / "out").string()};
}

// A tiny scale run, mono (one image per screen), `extra` flags added.
CliResult runTinyScale(const fs::path& root, const std::string& sizes, std::vector<std::string> extra = {}) {
    std::vector<std::string> args = tinyScaleArgs(root, sizes);
    args.push_back("--mono");
    args.insert(args.end(), extra.begin(), extra.end());
    return runCavewall(args);
}

TEST(BenchSceneCli, ScaleRunHasFourModesPerSize) {
    const test::TempFolder root("bench_cli_scale");
    const fs::path out = root / "out";
    std::vector<std::string> args = tinyScaleArgs(root.path(), "20k,40k");
    args.insert(args.end(), {"--stereo", "mono"});  // as --mono (cave4 is stereo)
    const CliResult r = runCavewall(args);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("4 screens at 32x32 pixels, mono"));
    EXPECT_THAT(r.out, HasSubstr("textures (those the stretch requests) at most 16 texels"));
    EXPECT_THAT(r.out, HasSubstr("texels: 0 rendered in"));  // the second size: all from the cache
    EXPECT_TRUE(fs::exists(root / "data" / "plant-20000" / "scene.json"));
    EXPECT_TRUE(fs::exists(root / "data" / "plant-20000" / "cavewall-plant.json"));  // the plant's stamp
    for (const char* file : {"scale.md", "scale_ms.png", "scale_mb.png", "scale_load.png"})
        EXPECT_TRUE(fs::exists(out / file)) << file;
    const test::CsvTable csv = test::readCsv(out / "scale.csv");
    ASSERT_EQ(csv.size(), 12u);
    EXPECT_EQ(csv.column("mode"),
              (std::vector<std::string>{"full", "full-lod", "near", "cells", "walls", "walls-budget", "full",
                                        "full-lod", "near", "cells", "walls", "walls-budget"}));
    for (std::size_t size : {0u, 6u}) {
        EXPECT_EQ(csv[size + 4].number("triangle_budget"), 0.0);
        EXPECT_GT(csv[size + 5].number("triangle_budget"), 0.0);
        EXPECT_LE(csv[size + 5].number("triangles_per_frame"), csv[size + 4].number("triangles_per_frame"));
        // The control draws the walls' cells without their quads, and no texture over alpha.
        EXPECT_LT(csv[size + 3].number("triangles_per_frame"), csv[size + 4].number("triangles_per_frame"));
        EXPECT_EQ(csv[size + 3].number("textures_over_alpha"), 0.0);
        // Full geometry with levels of detail (1 px) draws fewer triangles than at full detail.
        EXPECT_LT(csv[size + 1].number("triangles_per_frame"), csv[size].number("triangles_per_frame"));
    }
    EXPECT_THAT(r.out, HasSubstr("walls-budget (" + csv[5].at("triangle_budget") + " triangles a frame): speed-up"));
    EXPECT_THAT(r.out, HasSubstr("x against full geometry with levels of detail)"));
    EXPECT_THAT(r.out, HasSubstr("Against the control, cells without textures"));
    EXPECT_THAT(r.out, HasSubstr(" M triangles: cells "));
    for (const test::CsvRow& row : csv) {
        SCOPED_TRACE(row.at("mode"));
        EXPECT_GT(row.number("frame_ms_p50"), 0.0);
        EXPECT_GT(row.number("first_frame_s"), 0.0);
        EXPECT_LE(row.number("resident_mb"), row.number("whole_model_mb") + 1e-9);
        if (row.at("mode") == "walls" || row.at("mode") == "walls-budget" || row.at("mode") == "cells") {
            EXPECT_GT(row.number("paged_peak_mb"), 0.0);
            EXPECT_EQ(row.number("textures_over_alpha"), 0.0);
        }
        if (row.at("mode") == "full") {
            EXPECT_EQ(row.number("compared_frames"), 0.0);  // the reference
            EXPECT_EQ(row.at("psnr_db"), "inf");
        } else {
            // Frames 0 and 2 of 4 (--compare-every 2), against full geometry's images.
            EXPECT_EQ(row.number("compared_frames"), 2.0);
            EXPECT_GT(row.number("psnr_db"), 5.0);
            EXPECT_LE(row.number("worst_frame_psnr_db"), row.number("psnr_db") + 1e-9);
            EXPECT_GE(row.number("flip_mean"), 0.0);
            EXPECT_LE(row.number("flip_mean"), 1.0);
        }
    }
    // The near limit leaves out every cell but the viewer's: it must lose to full geometry
    // somewhere in the compared frames, and the walls (and the control, which draws at least
    // the viewer's cell) must do better than it.
    EXPECT_LT(csv[2].number("psnr_db"), 60.0);
    EXPECT_GE(csv[4].number("psnr_db"), csv[2].number("psnr_db"));
    EXPECT_GE(csv[3].number("psnr_db"), csv[2].number("psnr_db"));
    EXPECT_THAT(r.out, HasSubstr("textures over alpha"));
}

// cave4 in stereo (its default, no --mono): every compared mode's stereo error against full
// geometry's depth is reported, and the recommendation takes it into account. The near limit
// leaves out every cell but the viewer's, so its depth differs from full geometry's somewhere.
TEST(BenchSceneCli, ScaleRunInStereoReportsTheStereoError) {
    const test::TempFolder root("bench_cli_scale_stereo");
    const fs::path out = root / "out";
    std::vector<std::string> args = tinyScaleArgs(root.path(), "20k");
    args.insert(args.end(), {"--triangle-budget", "0"});
    const CliResult r = runCavewall(args);
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("4 screens at 32x32 pixels, separate"));
    EXPECT_THAT(r.out, HasSubstr("occlusion culling: on, in views whose list submits at least 100000 triangles in "
                                 "at least 500 draws, paused for 16 frames in a view where it saved under 10 % of "
                                 "them (every mode"));
    EXPECT_THAT(r.out, HasSubstr("stereo arcmin (% > 1')"));
    // Whether the walls are on the front at 32 x 32 pixels depends on their frame time against
    // full geometry with levels of detail (a few milliseconds apart): where they are, the rule
    // names the stereo error (recommend_test checks the rule itself).
    EXPECT_THAT(r.out, testing::ContainsRegex("recommended \\([0-9.]+ M triangles\\): (walls[-a-z]* \\(fastest of [0-9]+ "
                                              "walls modes? within 0.001 arcmin of the lowest mean stereo error|none "
                                              "\\(no walls mode is on the front\\))"));
    const test::CsvTable csv = test::readCsv(out / "scale.csv");
    ASSERT_EQ(csv.size(), 5u);                     // full, full-lod, near, cells, walls
    EXPECT_EQ(csv[0].at("stereo_arcmin"), "nan");  // the reference
    for (std::size_t m = 1; m < csv.size(); ++m) {
        SCOPED_TRACE(csv[m].at("mode"));
        EXPECT_GE(csv[m].number("stereo_arcmin"), 0.0);
        EXPECT_GE(csv[m].number("stereo_beyond_1arcmin"), 0.0);
        EXPECT_LE(csv[m].number("stereo_beyond_1arcmin"), 1.0);
        // The worst image's FLIP mean is at least the mean over all images (all of one size).
        EXPECT_GE(csv[m].number("worst_image_flip"), csv[m].number("flip_mean") - 1e-5);
        EXPECT_LE(csv[m].number("worst_image_flip"), 1.0);
    }
    EXPECT_GT(csv[2].number("stereo_arcmin"), 0.0);
    EXPECT_GT(csv[2].number("worst_image_flip"), 0.0);
}

// The depth images (<texture>.depth.tif) anywhere under a bake cache.
std::size_t depthImages(const fs::path& cache) {
    std::size_t n = 0;
    for (const auto& e : fs::recursive_directory_iterator(cache)) n += e.path().string().ends_with(".depth.tif");
    return n;
}

// --walls depth, --min-zone and --no-occlusion reach the scale bench's plan, bake and renderers
// (they were once accepted and ignored there): the report names them, the bake holds depth
// images, and the depth walls' own bound keeps every drawn texture within alpha.
TEST(BenchSceneCli, ScaleRunDrawsDepthWallsWithTheZonesAsked) {
    const test::TempFolder root("bench_cli_scale_depth");
    const fs::path out = root / "out";
    const CliResult r = runTinyScale(
        root.path(), "20k", {"--walls", "depth", "--min-zone", "2", "--triangle-budget", "0", "--no-occlusion"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("occlusion culling: off (--no-occlusion)"));
    EXPECT_THAT(r.out, HasSubstr("walls: depth walls at alpha 10 deg"));
    EXPECT_THAT(r.out, HasSubstr("walls planned (zones of at least 2.00 m)"));
    EXPECT_GT(depthImages(root / "data" / "bake-cache"), 0u);
    const test::CsvTable csv = test::readCsv(out / "scale.csv");
    ASSERT_EQ(csv.size(), 5u);  // full, full-lod, near, cells, walls (no budget)
    EXPECT_EQ(csv[4].at("mode"), "walls");
    EXPECT_EQ(csv[4].number("textures_over_alpha"), 0.0);
    EXPECT_EQ(csv[4].number("compared_frames"), 2.0);
}

// --walls flat,depth: the flat walls as usual and walls-depth beside them, planned with the
// depth bound and baked with depth, drawn in turn with the other modes; the report gives their
// frame-time ratio from this run. Every mode culls every list (--occlusion-min 0).
TEST(BenchSceneCli, ScaleRunDrawsDepthWallsBesideFlatOnes) {
    const test::TempFolder root("bench_cli_scale_both");
    const fs::path out = root / "out";
    const CliResult r = runTinyScale(
        root.path(), "20k",
        {"--walls", "flat,depth", "--triangle-budget", "0", "--occlusion-min", "0", "--occlusion-min-draws", "0"});
    ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
    EXPECT_THAT(r.out, HasSubstr("occlusion culling: on, in views whose list submits at least 0 triangles in at "
                                 "least 0 draws"));
    EXPECT_THAT(r.out, HasSubstr("walls: flat walls at alpha 10 deg"));
    EXPECT_THAT(r.out, HasSubstr("; walls-depth: the walls mode with depth walls"));
    EXPECT_THAT(r.out, HasSubstr("; depth walls planned (zones of at least"));
    EXPECT_GT(depthImages(root / "data" / "bake-cache"), 0u);
    const test::CsvTable csv = test::readCsv(out / "scale.csv");
    ASSERT_EQ(csv.size(), 6u);
    EXPECT_EQ(csv.column("mode"),
              (std::vector<std::string>{"full", "full-lod", "near", "cells", "walls", "walls-depth"}));
    for (const test::CsvRow& row : csv) {  // every list culled: what is in view is still drawn
        SCOPED_TRACE(row.at("mode"));
        EXPECT_GT(row.number("triangles_per_frame"), 0.0);
    }
    for (std::size_t m : {4u, 5u}) {
        EXPECT_EQ(csv[m].number("textures_over_alpha"), 0.0);
        EXPECT_EQ(csv[m].number("compared_frames"), 2.0);
        EXPECT_GT(csv[m].number("paged_peak_mb"), 0.0);
    }
    // The ratio line, against the CSV's medians (printed to 3 decimals).
    const std::string line = "M triangles: depth / flat ";
    const std::size_t at = r.out.find(line);
    ASSERT_NE(at, std::string::npos) << r.out;
    const double printed = std::strtod(r.out.c_str() + at + line.size(), nullptr);
    EXPECT_NEAR(printed, csv[5].number("frame_ms_p50") / csv[4].number("frame_ms_p50"), 0.002);
}

// A --data folder whose plant-N holds another model (here a house) is refused before it is
// benchmarked as the plant for N, and the folder is left as it was.
TEST(BenchSceneCli, ScaleRefusesAnotherModelInAPlantFolder) {
    const test::TempFolder root("bench_cli_scale_other");
    const fs::path folder = root / "data" / "plant-1000";
    const CliResult g = runCavewall({"generate", "house", "--triangles", "2000", "--out", folder.string()});
    ASSERT_EQ(g.exitCode, 0) << g.err;
    const CliResult r = runCavewall({"bench", "--mono", "--scale", "1k", "--resolution", "32", "--frames", "4",
                                     "--data", (root / "data").string(), "--out", (root / "out").string()});
    EXPECT_EQ(r.exitCode, 1) << r.out;
    EXPECT_THAT(r.err,
                HasSubstr("bench --scale: " + folder.string() + ": expected the plant generated for 1000 triangles ("));
    EXPECT_THAT(r.err, HasSubstr(" drawn triangles; remove the folder to generate the plant again, or give another "
                                 "--data"));
    EXPECT_FALSE(fs::exists(folder / "cavewall-plant.json"));
}

// Runs cavewall through sh after `prefix` (a file size limit) and under `launcher` (another
// user); stdout and stderr through files in `folder`.
CliResult runThroughShell(const std::string& prefix, const std::string& launcher, const std::vector<std::string>& args,
                          const fs::path& folder) {
    std::string command = prefix + " exec " + launcher + " '" + std::string(CAVEWALL_EXE) + "'";
    for (const std::string& a : args) command += " '" + a + "'";
    const fs::path out = folder / "stdout.txt", err = folder / "stderr.txt";
    const int status =
        std::system(("sh -c \"" + command + "\" > '" + out.string() + "' 2> '" + err.string() + "'").c_str());
    auto read = [](const fs::path& f) {
        std::ifstream in(f);
        return std::string(std::istreambuf_iterator<char>(in), {});
    };
    return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, read(out), read(err)};
}

// The files under `folder`, by name.
std::vector<std::string> filesUnder(const fs::path& folder) {
    std::vector<std::string> names;
    for (const auto& e : fs::recursive_directory_iterator(folder))
        if (e.is_regular_file()) names.push_back(e.path().filename().string());
    return names;
}

// `bench --scale`'s data folder on a full disk (a file size limit: the model's write fails as
// on a full disk) and read-only: the error names the file or folder and why, and no plant is
// left that a later run would reuse (a later run reuses a folder with a scene.json).
TEST(BenchSceneCli, ScaleDataFolderThatCannotBeWrittenIsNamedAndLeftUntrusted) {
    const test::TempFolder root("bench_cli_scale_unwritable");
    fs::permissions(root.path(), fs::perms::all);  // another user writes its files here
    const std::vector<std::string> args = {"bench", "--mono",   "--scale", "1k",    "--resolution",
                                           "32",    "--frames", "4",       "--data"};
    std::vector<std::string> full = args;
    full.insert(full.end(), {(root / "full").string(), "--out", (root / "out-full").string()});
    const CliResult r = runThroughShell("trap '' XFSZ; ulimit -f 8;", "", full, root.path());
    EXPECT_EQ(r.exitCode, 1) << r.out;
    const fs::path plant = root / "full" / "plant-1000";
    EXPECT_THAT(r.err, HasSubstr(plant.string() + "/plant.glb: cannot write (File too large; "));
    ASSERT_TRUE(fs::exists(plant));
    EXPECT_TRUE(filesUnder(plant).empty());  // no scene.json, no stamp, no temporary file

    // A data folder that cannot be made: its parent is a file (a read-only folder would need a
    // user other than root, whom file modes do not stop).
    test::writeFile(root / "a-file", "not a folder");
    std::vector<std::string> blocked = args;
    blocked.insert(blocked.end(), {(root / "a-file" / "data").string(), "--out", (root / "out-blocked").string()});
    const CliResult ro = runThroughShell("", "", blocked, root.path());
    EXPECT_EQ(ro.exitCode, 1) << ro.out;
    EXPECT_THAT(ro.err, HasSubstr((root / "a-file" / "data").string()));
    EXPECT_THAT(ro.err, HasSubstr("Not a directory"));
    EXPECT_FALSE(fs::exists(root / "out-blocked" / "scale.csv"));
}

}  // namespace
}  // namespace cavewall::test
