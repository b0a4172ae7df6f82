// bench.csv columns, bench.md and the plot of `cavewall bench` (app/bench/report.h).
#include "app/bench/plot.h"
#include "app/bench/report.h"

#include "scenes/image_io.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace cavewall::bench {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

using test::parseCsv;

ModeResult sample(Mode mode, double alpha, double p50, double rmse) {
    ModeResult m;
    m.mode = mode;
    m.alphaDeg = alpha;
    if (alpha > 0) m.transition = app::Transition::Blend;
    m.frameMs = {p50, p50 * 1.1, p50 * 1.2, p50};
    m.error.rmse = rmse;
    m.error.mse = rmse * rmse;
    m.error.psnrDb = rmse > 0 ? -20 * std::log10(rmse) : std::numeric_limits<double>::infinity();
    m.error.meanPsnrDb = std::min(m.error.psnrDb, kQuantisationPsnrDb);
    m.frames = {{p50, 1000.0, 4.0}, {p50 * 1.2, 1500.0, 4.0}};
    m.loadRatio = 1.5;  // as ModeAccumulator::finish reads it off m.frames
    ScreenResult front;
    front.screen = "front";
    front.error = m.error;
    m.screens = {front};
    return m;
}

TEST(BenchReport, CsvStartsWithTheRequiredColumns) {
    EXPECT_THAT(csvHeader(), StartsWith("mode,alpha_deg,transition,frame_ms_p50,frame_ms_p95,frame_ms_p99,speedup,"
                                        "psnr_db,rmse,ssim,max_err_deg,max_err_px,triangles,draw_calls,textures,"
                                        "disk_mb,gpu_mb"));
}

TEST(BenchReport, RowsMatchTheHeader) {
    // parseCsv fails when a row's cell count differs from the header's.
    const ModeResult m = sample(Mode::Walls, 2.5, 12.0, 0.01);
    const auto row = parseCsv(csvHeader() + "\n" + csvRow(m) + "\n")[0];
    EXPECT_EQ(row.at("mode"), "walls");
    EXPECT_EQ(row.at("alpha_deg"), "2.5");
    EXPECT_EQ(row.at("transition"), "blend");
    EXPECT_EQ(row.at("frame_ms_p50"), "12");
    EXPECT_EQ(row.at("psnr_db"), "40");  // PSNR of RMSE 0.01 = 20 log10(100)
    // The reference has infinite PSNR: written as "inf", which strtod reads back.
    const auto full = parseCsv(csvHeader() + "\n" + csvRow(sample(Mode::Full, 0, 30.0, 0.0)) + "\n")[0];
    EXPECT_EQ(full.at("psnr_db"), "inf");
    EXPECT_EQ(full.at("transition"), "none");
    EXPECT_TRUE(std::isinf(full.number("psnr_db")));
}

TEST(BenchReport, MarkdownHasOneRowPerMode) {
    BenchReport report;
    report.header = {"display: cave4"};
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Walls, 10, 3.0, 0.02)};
    const std::string md = markdownReport(report);
    EXPECT_THAT(md, HasSubstr("- display: cave4\n"));
    EXPECT_THAT(md, HasSubstr("| 1 | full | 30 / 33 / 36 |"));
    EXPECT_THAT(md, HasSubstr("| 2 | walls a=10 blend | 3 / 3.3 / 3.6 |"));
}

TEST(BenchReport, TargetsNameTheFastestWallsModeAbove30Db) {
    BenchReport report;
    ModeResult fastButBad = sample(Mode::Walls, 20, 1.0, 0.1);  // PSNR 20 dB: not eligible
    // Pooled 20 dB but a mean of 30.5 dB (images of 11 and 50 dB, say): eligible, slower.
    ModeResult meanOnly = sample(Mode::Walls, 15, 4.0, 0.1);
    meanOnly.error.meanPsnrDb = 30.5;
    meanOnly.speedup = 7.5;
    fastButBad.speedup = 30.0;
    ModeResult good = sample(Mode::Walls, 10, 2.0, 0.01);       // PSNR 40 dB
    good.speedup = 15.0;                                     // p99/p50 = 1.2 from sample()
    ModeResult near = sample(Mode::Near, 0, 1.6, 0.05);
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), near, fastButBad, meanOnly, good};
    const auto lines = targetLines(report);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_THAT(lines[0], HasSubstr("walls a=10 blend, speed-up 15 (>= 10: met)"));
    EXPECT_THAT(lines[0], HasSubstr("PSNR 40 dB mean (40 dB pooled)"));
    EXPECT_THAT(lines[0], HasSubstr("p99/p50 1.2 (<= 1.3: met)"));
    EXPECT_THAT(lines[0], HasSubstr("triangles drawn varying by 1.5"));  // 1500 / 1000
    EXPECT_THAT(lines[1], HasSubstr("1.25x the limit's"));  // 2.0 / 1.6
    EXPECT_THAT(lines[1], HasSubstr("<= 1.2: not met"));
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), near, fastButBad, meanOnly};
    EXPECT_THAT(targetLines(report)[0], HasSubstr("walls a=15 blend, speed-up 7.5 (>= 10: not met)"));
    EXPECT_THAT(targetLines(report)[0], HasSubstr("PSNR 30.5 dB mean (20 dB pooled)"));
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), fastButBad};
    EXPECT_THAT(targetLines(report), ::testing::ElementsAre(HasSubstr("no walls mode reaches a mean PSNR >= 30 dB")));
}

TEST(BenchReport, WritesFilesAndMarksTheFrontInThePlot) {
    const test::TempFolder folder("bench_report");
    BenchReport report;
    // full and the fast walls mode form the front; the slow, worse one is dominated.
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Walls, 10, 3.0, 0.02), sample(Mode::Walls, 20, 5.0, 0.05)};
    const auto files = writeReport(folder.path(), report);
    ASSERT_EQ(files.size(), 5u);
    const test::CsvTable frames = test::readCsv(folder / "bench_frames.csv");
    ASSERT_EQ(frames.size(), 3u * 2);  // 2 frames per mode
    EXPECT_EQ(frames.columns, (std::vector<std::string>{"mode", "frame", "frame_ms", "triangles", "draw_calls"}));
    // The second mode's second frame: 1.2 x its p50 of 3 ms.
    EXPECT_EQ(frames[3].at("mode"), "walls a=10 blend");
    EXPECT_EQ(frames[3].at("frame"), "1");
    EXPECT_EQ(frames[3].at("frame_ms"), "3.6");
    EXPECT_EQ(frames[3].at("triangles"), "1500");
    const test::CsvTable modes = test::readCsv(folder / "bench.csv");
    EXPECT_EQ(modes.column("mode"), (std::vector<std::string>{"full", "walls", "walls"}));
    EXPECT_EQ(modes.column("alpha_deg"), (std::vector<std::string>{"0", "10", "20"}));
    const scenes::Image png = scenes::readImage(folder / "bench.png");
    EXPECT_EQ(png.width, 640);
    EXPECT_EQ(png.height, 420);
    int red = 0, blue = 0;
    for (std::size_t i = 0; i < png.rgba.size(); i += 4) {
        red += png.rgba[i] == 210 && png.rgba[i + 1] == 30 && png.rgba[i + 2] == 30;
        blue += png.rgba[i] == 40 && png.rgba[i + 1] == 90 && png.rgba[i + 2] == 200;
    }
    EXPECT_GT(red, 2 * 49);  // two front markers (7x7) plus the line joining them
    EXPECT_GE(blue, 49);     // the dominated point
}

TEST(BenchPlot, DigitsAreDrawn) {
    scenes::Image image{"t", 20, 8, std::vector<std::uint8_t>(20 * 8 * 4, 0)};
    const unsigned char white[3] = {255, 255, 255};
    drawText(image, 0, 0, "18", 1, white);
    auto lit = [&](int x, int y) { return image.rgba[(y * 20 + x) * 4] == 255; };
    // '1' is 2,6,2,2,7: the middle column is lit on every row; '8' starts 4 pixels right and
    // its centre row is full (7).
    for (int y = 0; y < 5; ++y) EXPECT_TRUE(lit(1, y)) << y;
    EXPECT_TRUE(lit(4, 2) && lit(5, 2) && lit(6, 2));
    EXPECT_FALSE(lit(5, 1));  // the hole of the 8
}

}  // namespace
}  // namespace cavewall::bench
