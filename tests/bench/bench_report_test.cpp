// bench.csv columns, bench.md and the plot of `cavewall bench` (tools/bench_report.h).
#include "tools/bench_plot.h"
#include "tools/bench_report.h"

#include "scenes/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace cavewall::tools {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;

std::vector<std::string> split(const std::string& line) {
    std::vector<std::string> out;
    std::stringstream s(line);
    for (std::string field; std::getline(s, field, ',');) out.push_back(field);
    return out;
}

ModeResult sample(std::string mode, double alpha, double p50, double rmse) {
    ModeResult m;
    m.mode = std::move(mode);
    m.alphaDeg = alpha;
    m.transition = alpha > 0 ? "blend" : "none";
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
    const auto header = split(csvHeader());
    const ModeResult m = sample("walls", 2.5, 12.0, 0.01);
    const auto row = split(csvRow(m));
    ASSERT_EQ(row.size(), header.size());
    EXPECT_EQ(row[0], "walls");
    EXPECT_EQ(row[1], "2.5");
    EXPECT_EQ(row[2], "blend");
    EXPECT_EQ(row[3], "12");
    EXPECT_EQ(row[7], "40");  // PSNR of RMSE 0.01 = 20 log10(100)
    // The reference has infinite PSNR: written as "inf", which strtod reads back.
    const auto full = split(csvRow(sample("full", 0, 30.0, 0.0)));
    EXPECT_EQ(full[7], "inf");
    EXPECT_TRUE(std::isinf(std::strtod(full[7].c_str(), nullptr)));
}

TEST(BenchReport, MarkdownHasOneRowPerMode) {
    BenchReport report;
    report.header = {"display: cave4"};
    report.modes = {sample("full", 0, 30.0, 0.0), sample("walls", 10, 3.0, 0.02)};
    const std::string md = markdownReport(report);
    EXPECT_THAT(md, HasSubstr("- display: cave4\n"));
    EXPECT_THAT(md, HasSubstr("| 1 | full | 30 / 33 / 36 |"));
    EXPECT_THAT(md, HasSubstr("| 2 | walls a=10 blend | 3 / 3.3 / 3.6 |"));
}

TEST(BenchReport, TargetsNameTheFastestWallsModeAbove30Db) {
    BenchReport report;
    ModeResult fastButBad = sample("walls", 20, 1.0, 0.1);  // PSNR 20 dB: not eligible
    // Pooled 20 dB but a mean of 30.5 dB (images of 11 and 50 dB, say): eligible, slower.
    ModeResult meanOnly = sample("walls", 15, 4.0, 0.1);
    meanOnly.error.meanPsnrDb = 30.5;
    meanOnly.speedup = 7.5;
    fastButBad.speedup = 30.0;
    ModeResult good = sample("walls", 10, 2.0, 0.01);       // PSNR 40 dB
    good.speedup = 15.0;                                     // p99/p50 = 1.2 from sample()
    ModeResult near = sample("near", 0, 1.6, 0.05);
    report.modes = {sample("full", 0, 30.0, 0.0), near, fastButBad, meanOnly, good};
    const auto lines = targetLines(report);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_THAT(lines[0], HasSubstr("walls a=10 blend, speed-up 15 (>= 10: met)"));
    EXPECT_THAT(lines[0], HasSubstr("PSNR 40 dB mean (40 dB pooled)"));
    EXPECT_THAT(lines[0], HasSubstr("p99/p50 1.2 (<= 1.3: met)"));
    EXPECT_THAT(lines[0], HasSubstr("triangles drawn varying by 1.5"));  // 1500 / 1000
    EXPECT_THAT(lines[1], HasSubstr("1.25x the limit's"));  // 2.0 / 1.6
    EXPECT_THAT(lines[1], HasSubstr("<= 1.2: not met"));
    report.modes = {sample("full", 0, 30.0, 0.0), near, fastButBad, meanOnly};
    EXPECT_THAT(targetLines(report)[0], HasSubstr("walls a=15 blend, speed-up 7.5 (>= 10: not met)"));
    EXPECT_THAT(targetLines(report)[0], HasSubstr("PSNR 30.5 dB mean (20 dB pooled)"));
    report.modes = {sample("full", 0, 30.0, 0.0), fastButBad};
    EXPECT_THAT(targetLines(report), ::testing::ElementsAre(HasSubstr("no walls mode reaches a mean PSNR >= 30 dB")));
}

TEST(BenchReport, WritesFilesAndMarksTheFrontInThePlot) {
    const char* dir = std::getenv("CAVEWALL_TEST_OUTPUT");
    const std::filesystem::path folder = std::filesystem::path(dir ? dir : "/tmp") / "bench_report";
    std::filesystem::remove_all(folder);
    BenchReport report;
    // full and the fast walls mode form the front; the slow, worse one is dominated.
    report.modes = {sample("full", 0, 30.0, 0.0), sample("walls", 10, 3.0, 0.02), sample("walls", 20, 5.0, 0.05)};
    const auto files = writeReport(folder, report);
    ASSERT_EQ(files.size(), 5u);
    std::ifstream framesCsv(folder / "bench_frames.csv");
    std::vector<std::string> frameLines;
    for (std::string line; std::getline(framesCsv, line);) frameLines.push_back(line);
    ASSERT_EQ(frameLines.size(), 1u + 3 * 2);  // header + 2 frames per mode
    EXPECT_EQ(frameLines[0], "mode,frame,frame_ms,triangles,draw_calls");
    EXPECT_EQ(frameLines[4], "walls a=10 blend,1,3.6,1500,4");
    std::ifstream csv(folder / "bench.csv");
    int lines = 0;
    for (std::string line; std::getline(csv, line);) ++lines;
    EXPECT_EQ(lines, 4);  // header + 3 modes
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
}  // namespace cavewall::tools
