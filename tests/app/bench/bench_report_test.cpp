// bench.csv columns, bench.md and the plot of `cavewall bench` (app/bench/report.h,
// app/bench/report_plot.h).
#include "app/bench/demo_front.h"
#include "app/bench/report.h"
#include "app/bench/report_plot.h"

#include "scenes/image_io.h"
#include "tests/support/csv_table.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>

namespace cavewall::bench {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;

using test::parseCsv;

ModeResult sample(Mode mode, double alpha, double p50, double rmse) {
    ModeResult m;
    m.mode = mode;
    m.alphaDeg = alpha;
    if (alpha > 0) m.transition = app::Transition::Blend;
    m.frameMs = {p50, p50 * 1.1, p50 * 1.2, p50};
    m.error.frames = 2;
    m.error.rmse = rmse;
    m.error.mse = rmse * rmse;
    m.error.psnrDb = rmse > 0 ? -20 * std::log10(rmse) : std::numeric_limits<double>::infinity();
    m.error.meanPsnrDb = std::min(m.error.psnrDb, kQuantisationPsnrDb);
    m.error.worstFramePsnrDb = m.error.psnrDb - 3.0;
    m.error.p5FramePsnrDb = m.error.psnrDb - 2.0;
    m.error.flipMean = rmse;  // FLIP grows with the error in these samples
    m.error.flipOverThreshold = 4 * rmse;
    m.error.poppingPeak = 100 * rmse;
    m.error.poppingRms = 50 * rmse;
    m.frames = {{p50, 1000.0, 4.0}, {p50 * 1.2, 1500.0, 4.0}};
    m.loadRatio = 1.5;  // as ModeAccumulator::finish reads it off m.frames
    ScreenResult front;
    front.screen = "front";
    front.error = m.error;
    m.screens = {front};
    return m;
}

// The report gives figures only: no line judges one against a target (met, not met, or a
// target's threshold); docs/benchmarking.md does that.
void expectNoVerdicts(const std::vector<std::string>& lines) {
    for (const std::string& line : lines) {
        SCOPED_TRACE(line);
        for (const char* verdict : {"met)", "met;", ": met", "not met", "target", "<= 0.5", "<= 1.1", "<= 1.2",
                                    "<= 1.3", ">= 0.9", ">= 10", "<= 5 s", "no slower"})
            EXPECT_THAT(line, Not(HasSubstr(verdict)));
    }
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

TEST(BenchReport, EveryModeIsComparedWithFullGeometryWithLevelsOfDetail) {
    BenchReport report;
    report.modes = {sample(Mode::Full, 0, 215.0, 0.0), sample(Mode::Full, 0, 115.0, 0.01),
                    sample(Mode::Walls, 10, 73.0, 0.02)};
    report.modes[1].lodPixels = 1.0;  // the alternative a user would pick
    report.modes[2].lodPixels = 1.0;
    compareWithLodBaseline(report);
    EXPECT_EQ(lodBaseline(report), &report.modes[1]);
    EXPECT_NEAR(report.modes[2].speedupLod, 115.0 / 73.0, 1e-12);
    EXPECT_NEAR(report.modes[0].speedupLod, 115.0 / 215.0, 1e-12);  // full detail is slower than it
    const auto row = parseCsv(csvHeader() + "\n" + csvRow(report.modes[2]) + "\n")[0];
    EXPECT_NEAR(row.number("speedup_lod"), 115.0 / 73.0, 1e-3);
    // The Markdown table gives it in parentheses after the speed-up against full detail.
    EXPECT_THAT(markdownReport(report), HasSubstr(" (1.58) |"));
    // Without levels of detail there is no such baseline: NaN, and nothing in parentheses.
    BenchReport plain;
    plain.modes = {sample(Mode::Full, 0, 215.0, 0.0), sample(Mode::Walls, 10, 73.0, 0.02)};
    compareWithLodBaseline(plain);
    EXPECT_EQ(lodBaseline(plain), nullptr);
    EXPECT_TRUE(std::isnan(plain.modes[1].speedupLod));
    EXPECT_EQ(parseCsv(csvHeader() + "\n" + csvRow(plain.modes[1]) + "\n")[0].at("speedup_lod"), "nan");
}

TEST(BenchReport, LinesAreFittedByLeastSquares) {
    // y = 20 + 1.5 x exactly: slope, intercept and r2 1.
    const LineFit exact = fitLine({0, 10, 20, 30}, {20, 35, 50, 65});
    EXPECT_NEAR(exact.slope, 1.5, 1e-12);
    EXPECT_NEAR(exact.intercept, 20.0, 1e-12);
    EXPECT_NEAR(exact.r2, 1.0, 1e-12);
    EXPECT_EQ(exact.points, 4u);
    // (0, 0), (1, 2), (2, 1): mean x 1, mean y 1, sxy 1, sxx 2 -> slope 0.5, intercept 0.5;
    // syy 2 -> r2 = 1 / (2 * 2) = 0.25.
    const LineFit scattered = fitLine({0, 1, 2}, {0, 2, 1});
    EXPECT_NEAR(scattered.slope, 0.5, 1e-12);
    EXPECT_NEAR(scattered.intercept, 0.5, 1e-12);
    EXPECT_NEAR(scattered.r2, 0.25, 1e-12);
    EXPECT_EQ(fitLine({1}, {2}).points, 0u);        // one point: no line
    EXPECT_EQ(fitLine({3, 3}, {1, 2}).points, 0u);  // all x equal: no line
}

// A clusters mode held to `budget` ms whose frames take `frameMs`, predicted `predictedMs`
// for the drawn cost, with the controller's predicted frame time and floor.
ModeResult clustersAt(double budget, std::vector<double> frameMs, double floorMs) {
    ModeResult m = sample(Mode::Clusters, 0, 0, 0.05);
    m.frameBudgetMs = budget;
    m.frames.clear();
    for (std::size_t i = 0; i < frameMs.size(); ++i) {
        FrameSample f;
        f.frameMs = frameMs[i];
        f.predictedMs = frameMs[i] - 20.0;      // the fixed part: 20 ms
        f.predictedFrameMs = 0.9 * frameMs[i];  // 10 % low
        f.floorMs = floorMs;
        m.frames.push_back(f);
    }
    std::vector<double> sorted = frameMs;
    std::sort(sorted.begin(), sorted.end());
    m.frameMs.p50 = sorted[(sorted.size() - 1) / 2];
    m.frameMs.p95 = sorted[static_cast<std::size_t>(std::ceil(0.95 * static_cast<double>(sorted.size()))) - 1];
    return m;
}

TEST(BenchReport, ClusterBudgetLinesGiveP95OverTheBudgetOrInfeasibleAndFitThePrediction) {
    BenchReport report;
    report.resolution = "1024x1024 per screen, mono";
    report.noiseFloorP95Ratio = 1.25;
    report.modes = {sample(Mode::Full, 0, 300.0, 0.0),
                    clustersAt(50.0, {40, 45, 50, 52, 54}, 24.0),   // p95 54 = 1.08x the budget
                    clustersAt(30.0, {30, 34, 36, 38, 40}, 24.0),   // p95 40 = 1.33x the budget
                    clustersAt(16.0, {24, 25, 26, 27, 32}, 24.0)};  // floor 24 > 16: infeasible
    EXPECT_NEAR(p95OverBudget(report.modes[1]), 54.0 / 50.0, 1e-12);
    EXPECT_EQ(p95OverBudget(report.modes[0]), 0.0);  // no budget
    EXPECT_EQ(medianFloorMs(report.modes[1]), 24.0);
    const std::vector<std::string> lines = figureLines(report);
    auto has = [&](const std::string& text) {
        return std::any_of(lines.begin(), lines.end(),
                           [&](const std::string& l) { return l.find(text) != std::string::npos; });
    };
    EXPECT_TRUE(
        has("figures (1024x1024 per screen, mono): clusters frame 50ms: p50 50 ms, p95 54 ms = 1.08x the budget; "
            "floor (the cheapest selection's frame time, median) 24 ms; predicted frame time off by "
            "10 % (median), 10 % (p95)"));
    EXPECT_TRUE(has("clusters frame 30ms: p50 36 ms, p95 40 ms = 1.33x the budget; floor"));
    // A budget below the floor is a fact about the budget, not a judgement of the frames.
    EXPECT_TRUE(
        has("clusters frame 16ms: p50 26 ms, p95 32 ms = 2x the budget (infeasible: the floor is above the "
            "budget)"));
    EXPECT_TRUE(has("noise floor p95/p50 1.25"));
    // measured = 20 + 1 x predicted in every frame of the three modes.
    EXPECT_TRUE(has("over 15 frames: measured = 20 + 1 x predicted (r2 1;"));
    expectNoVerdicts(lines);
    // The CSV carries both per mode.
    const auto row = parseCsv(csvHeader() + "\n" + csvRow(report.modes[3]) + "\n")[0];
    EXPECT_EQ(row.number("p95_over_budget"), 2.0);
    EXPECT_EQ(row.number("floor_ms"), 24.0);
}

TEST(BenchReport, MarkdownHasOneRowPerMode) {
    BenchReport report;
    report.header = {"display: cave4"};
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Walls, 10, 3.0, 0.02)};
    const std::string md = markdownReport(report);
    EXPECT_THAT(md, HasSubstr("- display: cave4\n"));
    EXPECT_THAT(md, HasSubstr("| 1 | full | 30 / 33 / 36 |"));
    EXPECT_THAT(md, HasSubstr("| 2 | walls flat a=10 blend | 3 / 3.3 / 3.6 |"));
}

TEST(BenchReport, FiguresDescribeTheFastestWallsModeAtAlpha10WithLevelsOfDetailAbove32DbPooled) {
    BenchReport report;
    report.noiseFloorRatio = 1.1;
    auto walls = [](double alpha, double p50, double rmse, double speedup) {
        ModeResult m = sample(Mode::Walls, alpha, p50, rmse);
        m.lodPixels = 1.0;
        m.speedup = speedup;
        return m;
    };
    ModeResult fastButBad = walls(10, 1.0, 0.1, 30.0);  // PSNR 20 dB: not eligible
    // Pooled 20 dB but a capped mean of 40 dB: not eligible either, the capped mean ranks nothing.
    ModeResult meanOnly = walls(10, 1.5, 0.1, 20.0);
    meanOnly.error.meanPsnrDb = 40.0;
    ModeResult wideAlpha = walls(20, 1.2, 0.01, 25.0);  // 40 dB but alpha 20: not eligible
    ModeResult noLod = walls(10, 1.4, 0.01, 21.0);
    noLod.lodPixels = 0.0;                           // 40 dB but no levels of detail
    ModeResult at31 = walls(10, 1.8, 0.0282, 16.0);  // 31 dB: below the 32 dB bar
    ModeResult good = walls(10, 2.0, 0.01, 15.0);    // 40 dB; p99/p50 1.2 from sample()
    good.texturesOverAlpha = 0;
    at31.texturesOverAlpha = 2;                     // counted over every walls mode
    ModeResult steady = walls(10, 2.5, 0.01, 5.0);  // eligible, slower than `good`
    steady.loadRatio = 1.2;
    steady.transition = app::Transition::Warp;
    ModeResult paged = walls(10, 3.0, 0.01, 4.0);  // the only one that uploads
    paged.paged = true;
    paged.loadRatio = 1.2;
    paged.uploadedMB = {1.0, 1.4, 1.6, 1.1};
    ModeResult near = sample(Mode::Near, 0, 1.6, 0.05);
    near.lodPixels = 1.0;
    ModeResult control = sample(Mode::Cells, 0, 1.8, 0.04);  // FLIP mean 0.04
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0),
                    control,
                    near,
                    fastButBad,
                    meanOnly,
                    wideAlpha,
                    noLod,
                    at31,
                    good,
                    steady,
                    paged};
    compareWithControl(report);
    const auto lines = figureLines(report);
    ASSERT_EQ(lines.size(), 6u);
    EXPECT_EQ(lines[0], "figures: textures drawn over alpha in 8 walls modes: 2");
    EXPECT_THAT(lines[1],
                HasSubstr("walls flat a=10 blend lod 1px, speed-up 15, PSNR 40 dB pooled (worst frame 37 dB)"));
    // 0.01 / 0.04.
    EXPECT_THAT(lines[2], HasSubstr("FLIP mean is 0.25x the control's (cells, no textures; 0.01 against 0.04)"));
    // 1.2 / 1.1 = 1.09; triangles 1500 / 1000 = 1.5.
    EXPECT_THAT(lines[3], HasSubstr("p99/p50 is 1.2, 1.09x the noise floor (one frame drawn again and again: 1.1); "
                                    "per-frame work p99/p50: triangles 1.5, texture MB uploaded p50 0"));
    // Uploads are given where they happen, in the paged mode: 1.6 / 1.0.
    EXPECT_THAT(lines[4],
                HasSubstr("walls flat a=10 blend paged lod 1px: texture MB uploaded per frame p99/p50 1.6 (1.6 / 1)"));
    EXPECT_THAT(lines[5], HasSubstr("1.25x the limit's"));  // 2.0 / 1.6
    EXPECT_THAT(lines[5], HasSubstr("(2 ms against 1.6 ms)"));
    expectNoVerdicts(lines);
    // Without an eligible mode the closest in pooled PSNR is named with its figures.
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), control, near, fastButBad, at31};
    compareWithControl(report);
    const auto missed = figureLines(report);
    ASSERT_GE(missed.size(), 2u);
    EXPECT_THAT(missed[1], HasSubstr("reaches a pooled PSNR >= 32 dB; the closest, walls flat a=10 blend lod 1px, "
                                     "has 31 dB pooled at a speed-up of 16"));
    expectNoVerdicts(missed);
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), near};
    EXPECT_THAT(figureLines(report),
                ::testing::ElementsAre(HasSubstr("no walls mode at alpha <= 10 with levels of detail")));
}

// A --compare-scene mode is set against the bench scene's same mode, in speed-up and their
// ratio, and never stands in for the bench scene's own walls mode.
TEST(BenchReport, CompareSceneModesAreSetAgainstTheSameModeOfTheBenchScene) {
    BenchReport report;
    ModeResult own = sample(Mode::Walls, 10, 4.0, 0.02);
    own.speedup = 2.0;
    own.textures = 100;
    own.diskMB = 50.0;
    ModeResult warp = sample(Mode::Walls, 10, 8.0, 0.05);  // another transition: not its match
    warp.transition = app::Transition::Warp;
    warp.speedup = 1.0;
    ModeResult automatic = sample(Mode::Walls, 10, 4.6, 0.01);
    automatic.speedup = 1.74;
    automatic.textures = 120;
    automatic.diskMB = 61.0;
    automatic.sceneTag = "auto";
    ModeResult better = automatic;  // the same at alpha 20 with no match: no line
    better.alphaDeg = 20;
    report.modes = {sample(Mode::Full, 0, 8.0, 0.0), warp, own, automatic, better};
    EXPECT_EQ(modeLabel(automatic), "walls flat a=10 blend [auto]");
    const auto lines = figureLines(report);
    expectNoVerdicts(lines);
    std::vector<std::string> compare;
    for (const std::string& l : lines)
        if (l.find("[auto]") != std::string::npos) compare.push_back(l);
    ASSERT_EQ(compare.size(), 1u);
    // 1.74 / 2.0 = 0.87 of the hand-placed walls' speed-up.
    EXPECT_THAT(compare[0],
                HasSubstr("walls flat a=10 blend [auto] against walls flat a=10 blend: speed-up 1.74 against 2 "
                          "(ratio 0.87), PSNR 40 against 34 dB pooled"));
    EXPECT_THAT(compare[0], HasSubstr("120 against 100 textures, 61 against 50 MB on disk"));
    report.modes[3].speedup = 1.9;
    EXPECT_THAT(figureLines(report), ::testing::Contains(HasSubstr("(ratio 0.95), PSNR")));
    // bench.csv names the scene of every row.
    const auto rows = parseCsv(csvHeader() + "\n" + csvRow(own) + "\n" + csvRow(automatic) + "\n");
    EXPECT_EQ(rows[0].at("scene"), "bench");
    EXPECT_EQ(rows[1].at("scene"), "auto");
}

// Fallbacks of the on-demand mode counted off its frames.
TEST(BenchReport, FallbacksAreCountedOffTheFrames) {
    std::vector<FrameSample> frames(8);
    const int fallbacks[] = {3, 2, 0, 1, 0, 0, 0, 0};
    for (std::size_t i = 0; i < frames.size(); ++i) frames[i].geometryFallbacks = fallbacks[i];
    OnDemandFigures f;
    countFallbacks(frames, f);
    EXPECT_EQ(f.geometryFallbacks, 6);
    EXPECT_EQ(f.fallbackFrames, 3);
    EXPECT_EQ(f.fallbacksUntilFrame, 4);             // the last is frame index 3
    EXPECT_DOUBLE_EQ(f.firstQuarterFallbacks, 2.5);  // (3 + 2) / 2 frames
    EXPECT_DOUBLE_EQ(f.lastQuarterFallbacks, 0.0);
    countFallbacks({}, f);
    EXPECT_EQ(f.geometryFallbacks, 0);
    EXPECT_EQ(f.fallbacksUntilFrame, 0);
    EXPECT_DOUBLE_EQ(f.firstQuarterFallbacks, 0.0);
}

// The on-demand mode's line: first frame, fallbacks, textures baked and p99/p50 against the
// noise floor; it is never the fastest walls mode that the other figure lines describe.
TEST(BenchReport, TheOnDemandModeHasItsOwnFigureLine) {
    BenchReport report;
    report.noiseFloorRatio = 1.5;
    ModeResult warm = sample(Mode::Walls, 10, 4.0, 0.02);
    ModeResult cold = sample(Mode::Walls, 10, 5.0, 0.01);  // p99/p50 1.2 from sample()
    cold.lodPixels = 1.0;  // would be the fastest walls mode at alpha 10 if it were eligible (40 dB)
    cold.speedup = 50.0;
    cold.onDemand.emplace();
    cold.onDemand->firstFrameSeconds = 2.25;
    cold.onDemand->texturesMissingAtStart = 40;
    cold.onDemand->texturesBaked = 12;
    cold.frames[0].geometryFallbacks = 4;
    countFallbacks(cold.frames, *cold.onDemand);
    report.modes = {sample(Mode::Full, 0, 8.0, 0.0), warm, cold};
    EXPECT_EQ(transitionLabel(cold), "blend on demand");
    const auto lines = figureLines(report);
    EXPECT_THAT(lines, ::testing::Contains(HasSubstr("no walls mode at alpha <= 10 with levels of detail")));
    EXPECT_THAT(lines,
                ::testing::Contains(AllOf(
                    HasSubstr("walls flat a=10 blend on demand lod 1px from an empty cache: first frame 2.25 s after "
                              "the scene's load; 4 geometry fallbacks (wall-frames) in 1 of 2 frames, the last "
                              "in frame 1 (counted from 1)"),
                    HasSubstr("12 of 40 textures baked; frame p99/p50 1.2, 0.8x the noise floor (one frame drawn "
                              "again and again: 1.5)"))));
    expectNoVerdicts(lines);
    const auto row = parseCsv(csvHeader() + "\n" + csvRow(cold) + "\n")[0];
    EXPECT_EQ(row.at("transition"), "blend on demand");
    EXPECT_EQ(row.number("first_frame_s"), 2.25);
    EXPECT_EQ(row.number("geometry_fallbacks"), 4.0);
    EXPECT_EQ(row.number("textures_baked"), 12.0);
}

TEST(BenchReport, EveryModeIsComparedWithTheCellsControl) {
    BenchReport report;
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Cells, 0, 5.0, 0.04),
                    sample(Mode::Walls, 10, 3.0, 0.01), sample(Mode::Walls, 20, 2.0, 0.08)};
    ModeResult cellsWithLod = sample(Mode::Cells, 0, 4.0, 0.5);  // not the control: levels of detail
    cellsWithLod.lodPixels = 1.0;
    report.modes.insert(report.modes.begin() + 1, cellsWithLod);
    ASSERT_EQ(controlMode(report), &report.modes[2]);
    compareWithControl(report);
    std::string csv = csvHeader() + "\n";
    for (const ModeResult& m : report.modes) csv += csvRow(m) + "\n";
    const test::CsvTable table = parseCsv(csv);
    // 20 log10(0.04 / 0.01) = 12.04 dB gained; FLIP means 0.01 / 0.04.
    EXPECT_NEAR(table[3].number("psnr_gain_db"), 20 * std::log10(4.0), 1e-4);
    EXPECT_NEAR(table[3].number("flip_ratio"), 0.25, 1e-6);
    EXPECT_NEAR(table[4].number("psnr_gain_db"), -20 * std::log10(2.0), 1e-4);  // worse than the control
    EXPECT_NEAR(table[4].number("flip_ratio"), 2.0, 1e-6);
    EXPECT_NEAR(table[2].number("psnr_gain_db"), 0.0, 1e-12);  // the control itself
    EXPECT_NEAR(table[3].number("flip_mean"), 0.01, 1e-9);
    EXPECT_NEAR(table[3].number("flip_share_over_0.1"), 0.04, 1e-9);
    EXPECT_NEAR(table[3].number("popping_peak"), 1.0, 1e-9);
    EXPECT_NEAR(table[3].number("popping_rms"), 0.5, 1e-9);
    EXPECT_NEAR(table[3].number("worst_frame_psnr_db"), 37.0, 1e-4);
    EXPECT_NEAR(table[3].number("p5_frame_psnr_db"), 38.0, 1e-4);
    EXPECT_NEAR(table[3].number("mean_psnr_db"), 40.0, 1e-4);
    const std::string md = markdownReport(report);
    EXPECT_THAT(md, HasSubstr("| 12 / 0.25 |"));  // walls flat a=10's row: gain / ratio
    EXPECT_THAT(md, HasSubstr("capped mean PSNR dB (not ranked)"));
    // Without a control the columns are NaN.
    BenchReport none;
    none.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Walls, 10, 3.0, 0.01)};
    compareWithControl(none);
    EXPECT_TRUE(std::isnan(none.modes[1].psnrGainDb));
    EXPECT_TRUE(std::isnan(parseCsv(csvHeader() + "\n" + csvRow(none.modes[1]) + "\n")[0].number("flip_ratio")));
}

TEST(BenchReport, ModesWithLevelsOfDetailAreJudgedAgainstTheControlAtTheSameTolerance) {
    auto at = [](Mode mode, double alpha, double p50, double rmse, double lod) {
        ModeResult m = sample(mode, alpha, p50, rmse);
        m.lodPixels = lod;
        return m;
    };
    BenchReport report;
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), at(Mode::Full, 0, 20.0, 0.001, 1.0),
                    at(Mode::Cells, 0, 5.0, 0.04, 0.0),  at(Mode::Cells, 0, 4.0, 0.05, 1.0),
                    at(Mode::Walls, 10, 3.0, 0.01, 0.0), at(Mode::Walls, 10, 2.0, 0.02, 1.0)};
    report.modes[5].speedup = 15.0;
    ModeResult cellsElsewhere = at(Mode::Cells, 0, 4.0, 0.08, 2.0);  // another scene's: never a control
    cellsElsewhere.sceneTag = "other";
    report.modes.push_back(cellsElsewhere);
    report.modes.push_back(at(Mode::Walls, 10, 2.0, 0.02, 2.0));  // no cells of its own at 2 px
    EXPECT_EQ(controlFor(report, report.modes[4]), &report.modes[2]);
    EXPECT_EQ(controlFor(report, report.modes[5]), &report.modes[3]);
    EXPECT_EQ(controlFor(report, report.modes[7]), &report.modes[2]);  // falls back to full detail
    compareWithControl(report);
    EXPECT_NEAR(report.modes[4].flipRatio, 0.25, 1e-12);  // 0.01 / 0.04
    EXPECT_NEAR(report.modes[5].flipRatio, 0.4, 1e-12);   // 0.02 / 0.05, not 0.02 / 0.04
    EXPECT_NEAR(report.modes[5].psnrGainDb, 20 * std::log10(2.5), 1e-9);
    EXPECT_NEAR(report.modes[7].flipRatio, 0.5, 1e-12);   // 0.02 / 0.04
    EXPECT_NEAR(report.modes[3].psnrGainDb, 0.0, 1e-12);  // the control at 1 px against itself
    const auto lines = figureLines(report);
    const auto line = std::find_if(lines.begin(), lines.end(),
                                   [](const std::string& l) { return l.find("FLIP mean is") != std::string::npos; });
    ASSERT_NE(line, lines.end());
    EXPECT_THAT(*line, HasSubstr("FLIP mean is 0.4x the control's at the same tolerance (cells, no textures, LOD 1 "
                                 "px; 0.02 against 0.05), 0.5x the control's at full detail (0.04)"));
    // A caller's named control is every mode's.
    report.control = 2;
    EXPECT_EQ(controlFor(report, report.modes[5]), &report.modes[2]);
}

TEST(BenchReport, StereoErrorColumnsOnlyWhenMeasured) {
    ModeResult mono = sample(Mode::Walls, 10, 3.0, 0.01);
    ModeResult stereo = mono;
    stereo.error.stereoMeasured = true;
    // 1000 pixels summing 250 arcmin (a mean of 0.25), 40 of them beyond the threshold (4 %).
    stereo.error.stereo = {.pixels = 1000, .sumArcmin = 250.0, .beyond = 40};
    stereo.screens[0].error = stereo.error;
    const auto rows = parseCsv(csvHeader() + "\n" + csvRow(mono) + "\n" + csvRow(stereo) + "\n");
    EXPECT_TRUE(std::isnan(rows[0].number("stereo_mean_arcmin")));  // mono: not measured, not 0
    EXPECT_TRUE(std::isnan(rows[0].number("stereo_beyond_share")));
    EXPECT_DOUBLE_EQ(rows[1].number("stereo_mean_arcmin"), 0.25);
    EXPECT_DOUBLE_EQ(rows[1].number("stereo_beyond_share"), 0.04);
    BenchReport report;
    report.modes = {mono, stereo};
    const std::string md = markdownReport(report);
    EXPECT_THAT(md, HasSubstr("| stereo err arcmin mean / % > 1 arcmin |"));
    EXPECT_THAT(md, HasSubstr(" | 0.25 / 4 | "));         // the stereo row: mean / percent beyond
    // The mono row: FLIP mean / % of pixels over 0.1 (a share of 0.04), then no stereo figure.
    EXPECT_THAT(md, HasSubstr(" | 0.01 / 4 | - | "));
    EXPECT_THAT(md, HasSubstr("| FLIP mean / % > 0.1 |"));
}

TEST(BenchReport, WritesFilesAndThePlot) {
    const test::TempFolder folder("bench_report");
    BenchReport report;
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Walls, 10, 3.0, 0.02),
                    sample(Mode::Walls, 20, 5.0, 0.05)};
    report.modes[2].flipWorst.image = scenes::Image{"flip", 3, 2, std::vector<std::uint8_t>(3 * 2 * 4, 200)};
    report.modes[2].flipWorst.frame = 12;
    report.modes[1].comparedImages = {{0, 0, 0, 31.5, 0.02}, {6, 0, 0, 24.25, 0.125}};
    const auto files = writeReport(folder.path(), report);
    ASSERT_EQ(files.size(), 7u);  // the six reports and mode 3's FLIP map, the only one set
    EXPECT_EQ(files[6], folder / "flip_worst_3.png");
    EXPECT_EQ(scenes::readImage(files[6]).width, 3);
    const test::CsvTable compared = test::readCsv(folder / "bench_compared.csv");
    ASSERT_EQ(compared.size(), 2u);  // mode 2's two images, no others
    EXPECT_EQ(compared.columns, (std::vector<std::string>{"mode", "frame", "screen", "eye", "psnr_db", "flip_mean"}));
    EXPECT_EQ(compared[1].at("mode"), "walls flat a=10 blend");
    EXPECT_EQ(compared[1].at("frame"), "6");
    EXPECT_EQ(compared[1].at("screen"), "front");
    EXPECT_EQ(compared[1].at("psnr_db"), "24.25");
    EXPECT_EQ(compared[1].at("flip_mean"), "0.125");
    EXPECT_FALSE(std::filesystem::exists(folder / "flip_worst_2.png"));
    const test::CsvTable frames = test::readCsv(folder / "bench_frames.csv");
    ASSERT_EQ(frames.size(), 3u * 2);  // 2 frames per mode
    EXPECT_EQ(frames.columns,
              (std::vector<std::string>{"mode", "frame", "frame_ms", "triangles", "draw_calls", "uploaded_mb",
                                        "over_alpha", "predicted_ms", "predicted_frame_ms", "floor_ms",
                                        "geometry_fallbacks", "textures_baked", "kept_fallbacks"}));
    // The second mode's second frame: 1.2 x its p50 of 3 ms.
    EXPECT_EQ(frames[3].at("mode"), "walls flat a=10 blend");
    EXPECT_EQ(frames[3].at("frame"), "1");
    EXPECT_EQ(frames[3].at("frame_ms"), "3.6");
    EXPECT_EQ(frames[3].at("triangles"), "1500");
    const test::CsvTable modes = test::readCsv(folder / "bench.csv");
    EXPECT_EQ(modes.column("mode"), (std::vector<std::string>{"full", "walls", "walls"}));
    EXPECT_EQ(modes.column("alpha_deg"), (std::vector<std::string>{"0", "10", "20"}));
    // gnuplot drew it at the figure's size (its content: BenchPlot below and tests/app/bench/plot_test.cpp).
    const scenes::Image png = scenes::readImage(folder / "bench.png");
    EXPECT_EQ(png.width, 1600);
    EXPECT_EQ(png.height, 640);
}

// Every mode is named in the legend as bench.md numbers it, in both panels alike; the
// reference (exact: infinite PSNR, FLIP 0) has no point; the front is flagged, and the control
// and the best alternative are ringed.
TEST(BenchPlot, NamesEveryModeAndFlagsTheFrontControlAndAlternative) {
    BenchReport report;
    report.resolution = "256x256 per screen, mono";
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Full, 0, 20.0, 0.01),
                    sample(Mode::Cells, 0, 2.0, 0.08), sample(Mode::Walls, 10, 3.0, 0.02),
                    sample(Mode::Walls, 20, 5.0, 0.05)};
    report.modes[1].lodPixels = 1.0;  // full geometry with levels of detail: the alternative
    const Figure figure = tradeOffFigure(report);
    ASSERT_EQ(figure.panels.size(), 2u);
    EXPECT_GT(figure.legendWidth, 0);  // one legend for both panels
    EXPECT_EQ(figure.note, "#1 full is the reference: exact, not drawn");
    const std::vector<std::string> names{"#1 full", "#2 full lod 1px", "#3 cells", "#4 walls flat a=10 blend",
                                         "#5 walls flat a=20 blend"};
    for (const PlotPanel& panel : figure.panels) {
        SCOPED_TRACE(panel.title);
        EXPECT_THAT(panel.title, HasSubstr("256x256 per screen, mono"));
        EXPECT_EQ(axisLabel(panel.x), "median frame time, all screens (ms)");
        std::vector<std::string> seriesNames;
        for (const PlotSeries& s : panel.series) seriesNames.push_back(s.name);
        EXPECT_EQ(seriesNames, names);
        EXPECT_TRUE(panel.series[0].points.empty());  // the reference
        // Front (lower time and error): cells (2 ms), walls flat a=10 (3 ms, less error), full lod
        // (20 ms, less still); walls flat a=20 is slower and worse than a=10.
        std::vector<bool> front;
        for (std::size_t i = 1; i < panel.series.size(); ++i) front.push_back(panel.series[i].points.at(0).front);
        EXPECT_EQ(front, (std::vector<bool>{true, true, true, false}));
        EXPECT_TRUE(panel.series[2].points[0].control);
        EXPECT_TRUE(panel.series[1].points[0].bestAlternative);
        EXPECT_FALSE(panel.series[3].points[0].control || panel.series[3].points[0].bestAlternative);
        EXPECT_EQ(panel.controlName, "control: cells without textures");
        EXPECT_EQ(panel.alternativeName, "best alternative: full geometry with levels of detail");
    }
    EXPECT_EQ(axisLabel(figure.panels[0].y), "pooled PSNR (dB)");
    EXPECT_TRUE(figure.panels[1].y.log);
    EXPECT_NO_THROW(checkFigure(figure, "bench.png"));
}

// The demo's control is its cells run at the walls' level of detail, which the bench's rule
// (cells at full detail) does not take: the demo names it, and it is ringed in both panels as
// the bench's control is and is the yardstick of the walls' gain. Walls modes name their kind.
TEST(BenchPlot, RingsTheDemosControl) {
    auto error = [](double flipMean) {
        ImageError e;
        e.frames = 4;
        e.psnrDb = 30.0 - 100.0 * flipMean;
        e.rmse = flipMean;
        e.flipMean = flipMean;
        return e;
    };
    // The demo's four runs: full geometry (the reference), with levels of detail, the control,
    // the depth walls.
    const std::vector<DemoMode> runs = {
        {.medianMs = 900.0},
        {.mode = Mode::Full, .lodPixels = 1.0, .medianMs = 500.0, .error = error(0.001)},
        {.mode = Mode::Cells, .lodPixels = 1.0, .medianMs = 300.0, .error = error(0.008), .control = true},
        {.mode = Mode::Walls,
         .lodPixels = 1.0,
         .wallKind = walls::WallKind::Depth,
         .alphaDeg = 10.0,
         .medianMs = 400.0,
         .error = error(0.004)}};
    const BenchReport report = demoReport(runs, "32x32 per screen, mono");
    ASSERT_EQ(controlMode(report), &report.modes[2]);
    EXPECT_NEAR(report.modes[3].flipRatio, 0.5, 1e-12);  // 0.004 against the control's 0.008
    ModeResult flat = report.modes[3];
    flat.wallKind = walls::WallKind::Flat;
    EXPECT_EQ(modeLabel(flat), "walls flat a=10 blend lod 1px");
    const Figure figure = tradeOffFigure(report);
    for (const PlotPanel& panel : figure.panels) {
        SCOPED_TRACE(panel.title);
        ASSERT_EQ(panel.series.size(), 4u);
        EXPECT_EQ(panel.series[2].name, "#3 cells lod 1px");
        EXPECT_EQ(panel.series[3].name, "#4 walls depth a=10 blend lod 1px");
        EXPECT_TRUE(panel.series[2].points.at(0).control);
        EXPECT_TRUE(panel.series[1].points.at(0).bestAlternative);
        EXPECT_FALSE(panel.series[1].points.at(0).control || panel.series[3].points.at(0).control);
    }
    // Without the demo's word the bench's rule finds no control there.
    std::vector<DemoMode> unnamed = runs;
    unnamed[2].control = false;
    EXPECT_EQ(controlMode(demoReport(unnamed, "")), nullptr);
}

// A mode that compared no frame has no error to show, and a NaN frame time no place on the axis:
// both keep their legend entry without a point rather than being drawn as exact.
TEST(BenchPlot, ModesWithoutFiguresHaveNoPoint) {
    BenchReport report;
    report.modes = {sample(Mode::Full, 0, 30.0, 0.0), sample(Mode::Walls, 10, 3.0, 0.02),
                    sample(Mode::Walls, 20, std::numeric_limits<double>::quiet_NaN(), 0.05),
                    sample(Mode::Walls, 30, 4.0, 0.04)};
    report.modes[1].error.frames = 0;
    const Figure figure = tradeOffFigure(report);
    for (const PlotPanel& panel : figure.panels) {
        ASSERT_EQ(panel.series.size(), 4u);
        EXPECT_TRUE(panel.series[1].points.empty());
        EXPECT_TRUE(panel.series[2].points.empty());
        ASSERT_EQ(panel.series[3].points.size(), 1u);
        EXPECT_TRUE(panel.series[3].points[0].front);  // alone, so on the front
    }
    EXPECT_NO_THROW(checkFigure(figure, "bench.png"));
}

}  // namespace
}  // namespace cavewall::bench
