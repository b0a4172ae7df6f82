// `cavewall bench --scale`'s report (app/bench/scale.h): slopes, the size list, the path
// stretch and the files.
#include "app/bench/scale.h"

#include "config/error.h"
#include "scenes/image_io.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

namespace cavewall::bench {
namespace {

using ::testing::HasSubstr;

ScaleRow row(std::size_t triangles, ScaleMode mode, double p50) {
    ScaleRow r;
    r.targetTriangles = r.triangles = triangles;
    r.mode = mode;
    r.frameMs = {p50, p50, p50, p50};
    // Walls apart from full in every plot: less memory, a later first frame.
    r.residentMB = mode == ScaleMode::Walls ? 1.0 : static_cast<double>(triangles) / 1e6;
    r.loadSeconds = 0.5;
    r.firstFrameSeconds = mode == ScaleMode::Walls ? 3.0 : 1.0;
    return r;
}

// Full grows by 10 ms per M triangles (20 ms at 2 M, 80 ms at 8 M); walls by 0.5 ms per M
// (5 ms at 2 M, 8 ms at 8 M), so walls at 8 M are 1.6x their 2 M time and full 4x.
ScaleReport sample() {
    ScaleReport r;
    r.header = {"display: test"};
    r.rows = {row(2'000'000, ScaleMode::Full, 20.0), row(2'000'000, ScaleMode::Walls, 5.0),
              row(8'000'000, ScaleMode::Full, 80.0), row(8'000'000, ScaleMode::Walls, 8.0)};
    return r;
}

TEST(BenchScale, SlopesAreLeastSquaresInMsPerMillionTriangles) {
    const ScaleReport r = sample();
    EXPECT_NEAR(msPerMillionTriangles(r, ScaleMode::Full), 10.0, 1e-9);
    EXPECT_NEAR(msPerMillionTriangles(r, ScaleMode::Walls), 0.5, 1e-9);
    EXPECT_NEAR(growth(r, ScaleMode::Full), 4.0, 1e-12);
    EXPECT_NEAR(growth(r, ScaleMode::Walls), 1.6, 1e-12);
    EXPECT_TRUE(std::isnan(msPerMillionTriangles(r, ScaleMode::Near)));  // no rows
    EXPECT_THAT(scaleMarkdown(r), HasSubstr("- full: 10.000 ms per M triangles, 4.00x"));
    // A mode with fewer than two sizes (here none) says so instead of printing nan.
    EXPECT_THAT(scaleMarkdown(r), HasSubstr("- near: no slope (it needs two sizes or more)"));
    EXPECT_THAT(scaleMarkdown(r), ::testing::Not(HasSubstr("nan")));
}

// The budgeted walls get their own row, CSV budget and speed-up line; a report without them
// prints neither their slope nor their line.
TEST(BenchScale, BudgetedWallsReportTheirBudgetBesideTheirSpeedUp) {
    ScaleReport r = sample();
    EXPECT_THAT(scaleMarkdown(r), ::testing::Not(HasSubstr("walls-budget")));
    ScaleRow budgeted = row(8'000'000, ScaleMode::WallsBudget, 4.0);
    budgeted.triangleBudget = 180'000;
    budgeted.comparedFrames = 5;
    budgeted.psnrDb = 31.8;
    budgeted.worstFramePsnrDb = 31.1;
    budgeted.flipMean = 0.0121;
    r.rows.push_back(budgeted);
    const std::string md = scaleMarkdown(r);
    EXPECT_THAT(md, HasSubstr("- 8.00 M triangles, walls-budget (180000 triangles a frame): speed-up 20.00x, pooled "
                              "PSNR 31.8 dB (worst frame 31.1 dB), FLIP mean 0.0121 over 5 compared frames"));
    EXPECT_THAT(md, HasSubstr("- 8.00 M triangles, walls: speed-up 10.00x"));
    EXPECT_THAT(md, HasSubstr("- walls-budget: no slope"));
    EXPECT_THAT(scaleCsv(r), HasSubstr(",walls-budget,180000,4.000,"));
    EXPECT_THAT(scaleCsv(r), HasSubstr(",walls,0,8.000,"));
}

// Full geometry with levels of detail, the alternative a user would pick, gets its row and every
// walls mode's speed-up against it beside the one against full detail.
TEST(BenchScale, WallsAreComparedWithFullGeometryWithLevelsOfDetail) {
    ScaleReport r = sample();
    EXPECT_THAT(scaleMarkdown(r), ::testing::Not(HasSubstr("against full geometry with levels of detail)")));
    r.rows.push_back(row(8'000'000, ScaleMode::FullLod, 16.0));
    const std::string md = scaleMarkdown(r);
    EXPECT_THAT(md, HasSubstr("- 8.00 M triangles, walls: speed-up 10.00x (2.00x against full geometry with levels "
                              "of detail), "));
    EXPECT_THAT(md, HasSubstr("- 2.00 M triangles, walls: speed-up 4.00x, "));  // no full-lod row at 2 M
    EXPECT_THAT(scaleCsv(r), HasSubstr(",full-lod,0,16.000,"));
}

// Depth walls drawn beside flat ones get their own row, slope and speed-up line, and a line of
// their median frame time over the flat walls' at each size; a report without them has none.
TEST(BenchScale, DepthWallsBesideFlatOnesReportTheirRatio) {
    ScaleReport r = sample();
    EXPECT_THAT(scaleMarkdown(r), ::testing::Not(HasSubstr("walls-depth")));
    EXPECT_THAT(scaleMarkdown(r), ::testing::Not(HasSubstr("depth / flat")));
    r.rows.push_back(row(2'000'000, ScaleMode::DepthWalls, 6.5));
    r.rows.push_back(row(8'000'000, ScaleMode::DepthWalls, 10.0));
    const std::string md = scaleMarkdown(r);
    EXPECT_THAT(md, HasSubstr("- 2.00 M triangles: depth / flat 1.300 (6.50 / 5.00 ms)"));
    EXPECT_THAT(md, HasSubstr("- 8.00 M triangles: depth / flat 1.250 (10.00 / 8.00 ms)"));
    EXPECT_THAT(md, HasSubstr("- walls-depth: 0.583 ms per M triangles"));
    EXPECT_THAT(md, HasSubstr("- 8.00 M triangles, walls-depth: speed-up 8.00x"));
    EXPECT_THAT(scaleCsv(r), HasSubstr(",walls-depth,0,10.000,"));
}

// The control (cells without textures) gets its row and a line per size setting each walls
// mode's pooled PSNR and FLIP against it; a report without it has no such line.
TEST(BenchScale, TheControlSetsEachWallsModeAgainstIt) {
    ScaleReport r = sample();
    EXPECT_THAT(scaleMarkdown(r), ::testing::Not(HasSubstr("Against the control")));
    auto compared = [](ScaleRow row, double psnr, double worst, double flip) {
        row.comparedFrames = 5;
        row.psnrDb = psnr;
        row.worstFramePsnrDb = worst;
        row.flipMean = flip;
        return row;
    };
    r.rows = {row(2'000'000, ScaleMode::Full, 20.0), compared(row(2'000'000, ScaleMode::Cells, 4.0), 26.0, 24.5, 0.04),
              compared(row(2'000'000, ScaleMode::Walls, 5.0), 34.5, 32.5, 0.01),
              compared(row(2'000'000, ScaleMode::DepthWalls, 6.5), 39.2, 38.0, 0.004)};
    const std::string md = scaleMarkdown(r);
    EXPECT_THAT(md, HasSubstr("- 2.00 M triangles: cells 26.0 dB (worst frame 24.5 dB), FLIP mean 0.0400; walls "
                              "+8.5 dB, FLIP 0.25x; walls-depth +13.2 dB, FLIP 0.10x"));
    EXPECT_THAT(md, HasSubstr("| 2.00 M | 0 | cells | 4.00 |"));
    EXPECT_THAT(scaleCsv(r), HasSubstr(",cells,0,4.000,"));
}

TEST(BenchScale, SizeListTakesSuffixesAndRejectsBadEntries) {
    EXPECT_EQ(parseScaleList("2M,500k,8000000"), (std::vector<std::size_t>{2'000'000, 500'000, 8'000'000}));
    EXPECT_EQ(parseScaleList("1.5M"), std::vector<std::size_t>{1'500'000});
    EXPECT_EQ(parseScaleList("128M,1"), (std::vector<std::size_t>{128'000'000, 1}));  // the plant's limits
    // What strtod would read but the help does not promise ("2M, 500k or 8000000").
    const std::string form =
        "expected a triangle count such as 2M, 500k or 8000000 (decimal digits, then k or M; "
        "at least 1)";
    // The generator makes plants up to 128 M triangles (512 bays): larger targets would run
    // for minutes and then not be met.
    const std::string limit =
        "expected at most 128000000 triangles (128M, the largest plant the generator makes), got ";
    const struct {
        const char* list;
        std::string message;
    } cases[] = {
        {"2M,x", "entry 2 'x': " + form},
        {"", "entry 1 '': " + form},
        {"0x400", "entry 1 '0x400': " + form},
        {"1e6", "entry 1 '1e6': " + form},
        {"-5k", "entry 1 '-5k': " + form},
        {" 5k", "entry 1 ' 5k': " + form},
        {"1..5M", "entry 1 '1..5M': " + form},
        {"M", "entry 1 'M': " + form},
        {"0", "entry 1 '0': " + form},
        {"inf", "entry 1 'inf': " + form},
        {"129M", "entry 1 '129M': " + limit + "129000000"},
        {"1k,1000M", "entry 2 '1000M': " + limit + "1000000000"},
        {"2147483647", "entry 1 '2147483647': " + limit + "2147483647"},
        {"4096M", "entry 1 '4096M': " + limit + "4096000000"},
        {"99999999999999999999M", "entry 1 '99999999999999999999M': " + limit + "more"},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.list);
        EXPECT_THAT([&] { parseScaleList(c.list); },
                    ::testing::ThrowsMessage<Error>(HasSubstr("bench: --scale: " + c.message)));
    }
}

// A reused plant folder holds the plant asked for: its stamp names the target and the drawn
// triangles; a folder from before stamps is checked against the plant made again, then stamped.
TEST(BenchScale, APlantFolderHoldingAnotherModelIsRefused) {
    const test::TempFolder root("bench_scale_plant");
    const auto never = []() -> std::size_t {
        ADD_FAILURE() << "a stamped folder needs no plant made again";
        return 0;
    };
    writePlantStamp(root / "stamped", 1000, 52'000);
    EXPECT_NO_THROW(checkPlantFolder(root / "stamped", 1000, 52'000, never));
    // Without a stamp, a model with the plant's triangles passes and is stamped.
    std::filesystem::create_directories(root / "old");
    EXPECT_NO_THROW(checkPlantFolder(root / "old", 1000, 52'000, [] { return std::size_t{52'000}; }));
    EXPECT_TRUE(std::filesystem::exists(root / "old" / kPlantStamp));
    EXPECT_NO_THROW(checkPlantFolder(root / "old", 1000, 52'000, never));
    std::filesystem::create_directories(root / "other");
    test::writeFile(root / "broken" / kPlantStamp, "{\"target\": \"many\"}");
    const std::string fix = "; remove the folder to generate the plant again, or give another --data";
    const struct {
        const char* name;
        std::filesystem::path folder;
        std::size_t target, triangles;
        std::string message;
    } cases[] = {
        {"another model, stamped", root / "stamped", 1000, 7'000,
         "expected the plant generated for 1000 triangles (52000 drawn), got a model of 7000 drawn triangles" + fix},
        {"another target's plant", root / "stamped", 2000, 52'000,
         "expected the plant generated for 2000 triangles, got one for 1000 (cavewall-plant.json)" + fix},
        {"another model, no stamp", root / "other", 1000, 7'000,
         "expected the plant generated for 1000 triangles (52000 drawn), got a model of 7000 drawn triangles" + fix},
        {"a broken stamp", root / "broken", 1000, 52'000, "expected a readable cavewall-plant.json, got "},
    };
    for (const auto& c : cases) {
        SCOPED_TRACE(c.name);
        EXPECT_THAT(
            [&] { checkPlantFolder(c.folder, c.target, c.triangles, [] { return std::size_t{52'000}; }); },
            ::testing::ThrowsMessage<Error>(HasSubstr("bench --scale: " + c.folder.string() + ": " + c.message)));
    }
    EXPECT_FALSE(std::filesystem::exists(root / "other" / kPlantStamp));  // a refused folder is not stamped
}

TEST(BenchScale, PathPrefixCutsThePolylineAtTheLength) {
    const std::vector<glm::dvec3> path{{0, 0, 0}, {10, 0, 0}, {10, 0, 10}};
    // 15 m: all of the first leg and half of the second.
    EXPECT_EQ(pathPrefix(path, 15.0), (std::vector<glm::dvec3>{{0, 0, 0}, {10, 0, 0}, {10, 0, 5}}));
    EXPECT_EQ(pathPrefix(path, 10.0), (std::vector<glm::dvec3>{{0, 0, 0}, {10, 0, 0}}));
    EXPECT_EQ(pathPrefix(path, 100.0), path);  // shorter than asked: all of it
}

TEST(BenchScale, WritesCsvMarkdownAndPlots) {
    const test::TempFolder folder("bench_scale");
    const auto files = writeScaleReport(folder.path(), sample());
    ASSERT_EQ(files.size(), 5u);
    const test::CsvTable csv = test::readCsv(folder / "scale.csv");
    ASSERT_EQ(csv.size(), 4u);
    EXPECT_EQ(csv.column("mode"), (std::vector<std::string>{"full", "walls", "full", "walls"}));
    EXPECT_EQ(csv[2].number("frame_ms_p50"), 80.0);
    EXPECT_EQ(csv[3].number("triangles"), 8e6);
    for (std::size_t i = 2; i < 5; ++i) {  // drawn by gnuplot at the scale figure's size
        const scenes::Image png = scenes::readImage(files[i]);
        EXPECT_EQ(png.width, 900);
        EXPECT_EQ(png.height, 640);
    }
    EXPECT_THAT(test::readFile(folder / "scale.md"), HasSubstr("one named line per mode that ran"));
}

// The worst compared image's FLIP and, where measured (stereo), the stereo error: mean arc
// minutes and the share beyond 1 arcmin; nan in the CSV and a dash in the table where not.
TEST(BenchScale, StereoErrorAndWorstImageFlipAreReported) {
    ScaleReport report = sample();
    ScaleRow& walls = report.rows[1];
    walls.comparedFrames = 5;
    walls.psnrDb = 34.4;
    walls.worstFramePsnrDb = 32.5;
    walls.flipMean = 0.0066;
    walls.worstImageFlip = 0.0324;
    walls.stereoMeasured = true;
    walls.stereo.pixels = 1000;
    walls.stereo.sumArcmin = 73.7;
    walls.stereo.beyond = 11;
    const test::CsvTable csv = test::parseCsv(scaleCsv(report));
    ASSERT_EQ(csv.size(), 4u);
    EXPECT_DOUBLE_EQ(csv[1].number("worst_image_flip"), 0.0324);
    EXPECT_DOUBLE_EQ(csv[1].number("stereo_arcmin"), 0.0737);
    EXPECT_DOUBLE_EQ(csv[1].number("stereo_beyond_1arcmin"), 0.011);
    EXPECT_EQ(csv[0].at("stereo_arcmin"), "nan");  // full geometry: the reference
    const std::string md = scaleMarkdown(report);
    EXPECT_THAT(md, HasSubstr("| worst image FLIP | stereo arcmin (% > 1') |"));
    EXPECT_THAT(md, HasSubstr("| 34.4 (32.5) | 0.0066 | 0.0324 | 0.0737 (1.10 %) |"));
}

}  // namespace
}  // namespace cavewall::bench
