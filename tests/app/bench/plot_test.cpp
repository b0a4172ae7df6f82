// Plot descriptions, their gnuplot scripts (app/bench/plot.h) and the gnuplot runner
// (app/bench/gnuplot.h). The runner's tests need gnuplot (tools/install-deps.sh installs it).
#include "app/bench/gnuplot.h"
#include "app/bench/plot.h"

#include "config/error.h"
#include "scenes/image_io.h"
#include "tests/support/files.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace cavewall::bench {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

// Two modes as markers, the second on the front and ringed as the control; a third on the
// front and ringed as the best alternative.
Figure sampleFigure() {
    PlotPanel panel;
    panel.title = "Pooled PSNR against frame time";
    panel.x = {"median frame time", "ms"};
    panel.y = {"pooled PSNR", "dB", false};
    panel.controlName = "control: cells without textures";
    panel.alternativeName = "best alternative: full geometry with levels of detail";
    panel.series = {{.name = "walls a=10 blend", .points = {{4.0, 30.0}}},
                    {.name = "cells", .points = {{2.0, 25.0, true, true, false}}},
                    {.name = "full lod 1px", .points = {{9.0, 40.0, true, false, true}}}};
    Figure figure;
    figure.panels = {panel};
    figure.width = 480;
    figure.height = 320;
    return figure;
}

std::size_t count(const std::string& text, const std::string& what) {
    std::size_t n = 0;
    for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
    return n;
}

// The sample figure's script, line by line: axes titled with their units, the terminal's size
// and output, the front as one line through its points in x order, and the control and the
// best alternative ringed and named.
TEST(PlotScript, TheSampleScriptStatesEachPart) {
    const std::string script = gnuplotScript(sampleFigure(), "/tmp/x/out.png");
    const struct {
        const char* what;
        const char* line;
    } expected[] = {
        {"x title", "set xlabel 'median frame time (ms)'"},
        {"y title", "set ylabel 'pooled PSNR (dB)'"},
        {"panel title", "set title 'Pooled PSNR against frame time'"},
        // Time from 0 to 9 ms plus 8 % of that span; PSNR (not from zero) 25 to 40 dB, 8 % of
        // the 15 dB span (1.2 dB) beyond each end.
        {"x range", "set xrange [0:9.72]"},
        {"y range", "set yrange [23.8:41.2]"},
        {"terminal", "set terminal pngcairo size 480,320 noenhanced"},
        {"output", "set output '/tmp/x/out.png'"},
        // The cells point (2 ms) and the full-geometry one (9 ms), in that order; not the walls one.
        {"front points", "$p0_front << EOD\n2 25\n9 40\nEOD\n"},
        {"front line", "$p0_front using 1:2 with lines"},
        {"front name", "title 'Pareto front'"},
        {"control point", "$p0_control << EOD\n2 25\nEOD\n"},
        {"alternative point", "$p0_alternative << EOD\n9 40\nEOD\n"},
        {"control ring", "$p0_control using 1:2 with points pt 6 ps 3"},
        {"control name", "title 'control: cells without textures'"},
        {"alternative name", "title 'best alternative: full geometry with levels of detail'"},
    };
    for (const auto& e : expected) {
        SCOPED_TRACE(e.what);
        EXPECT_THAT(script, HasSubstr(e.line));
    }
}

TEST(PlotScript, ARatioAxisHasNoUnit) { EXPECT_EQ(axisLabel({"FLIP mean", ""}), "FLIP mean"); }

TEST(PlotScript, EverySeriesIsNamedInTheLegend) {
    const std::string script = gnuplotScript(sampleFigure(), "out.png");
    for (const char* name : {"walls a=10 blend", "cells", "full lod 1px"})
        EXPECT_EQ(count(script, std::string("title '") + name + "'"), 1u) << name;
    // Markers only (size 1.4; the rings are 3): these series are not lines.
    EXPECT_EQ(count(script, "with points pt"), 5u);
    EXPECT_EQ(count(script, "ps 1.4"), 3u);
    EXPECT_THAT(script, Not(HasSubstr("linespoints")));
}

TEST(PlotScript, WithoutFlagsThereIsNoFrontControlOrAlternative) {
    Figure figure = sampleFigure();
    for (PlotSeries& s : figure.panels[0].series) s.points[0] = {s.points[0].x, s.points[0].y};
    const std::string script = gnuplotScript(figure, "out.png");
    EXPECT_THAT(script, Not(HasSubstr("Pareto front")));
    EXPECT_THAT(script, Not(HasSubstr("control")));
    EXPECT_THAT(script, Not(HasSubstr("alternative")));
}

TEST(PlotScript, LineSeriesAreJoinedInXOrder) {
    Figure figure = sampleFigure();
    figure.panels[0].series = {{.name = "walls", .points = {{8.0, 3.0}, {2.0, 1.0}}, .style = SeriesStyle::Line}};
    const std::string script = gnuplotScript(figure, "out.png");
    EXPECT_THAT(script, HasSubstr("$p0_s0 << EOD\n2 1\n8 3\nEOD\n"));
    EXPECT_THAT(script, HasSubstr("with linespoints"));
}

TEST(PlotScript, QuotesInNamesAreEscaped) {
    // gnuplot's single-quoted strings take '' for a quote and nothing else specially; enhanced
    // text is off, so '_' and '^' print as they are.
    EXPECT_EQ(gnuplotQuoted("it's"), "'it''s'");
    EXPECT_EQ(gnuplotQuoted("a\nb"), "'a b'");
    EXPECT_EQ(gnuplotQuoted("x_1^2 \"q\" \\n"), "'x_1^2 \"q\" \\n'");
    Figure figure = sampleFigure();
    figure.panels[0].series[0].name = "walls 'auto'";
    figure.panels[0].title = "it's";
    const std::string script = gnuplotScript(figure, "o'k.png");
    EXPECT_THAT(script, HasSubstr("title 'walls ''auto'''"));
    EXPECT_THAT(script, HasSubstr("set title 'it''s'"));
    EXPECT_THAT(script, HasSubstr("set output 'o''k.png'"));
}

TEST(PlotScript, LogarithmicAxesSpanTheirDataByAFactor) {
    Figure figure = sampleFigure();
    figure.panels[0].y.log = true;
    const std::string script = gnuplotScript(figure, "out.png");
    EXPECT_THAT(script, HasSubstr("set logscale y"));
    EXPECT_THAT(script, HasSubstr("unset logscale x"));
    EXPECT_THAT(script, HasSubstr("set yrange [20:50]"));  // 25 / 1.25 to 40 x 1.25
    figure.panels[0].series[0].points[0].y = 0.0;
    EXPECT_THAT([&] { checkFigure(figure, "f.png"); },
                ::testing::ThrowsMessage<Error>(HasSubstr(
                    "series 'walls a=10 blend': point 1: expected x and y > 0 on a logarithmic axis, got x=4 y=0")));
}

TEST(PlotScript, ALogarithmicAxisWithinOneDecadeStillCarriesNumbers) {
    // gnuplot labels powers of ten only: 0.0024 to 0.0075 would show no number at all.
    EXPECT_EQ(logTicks(0.0024, 0.0075), (std::vector<double>{0.003, 0.004, 0.005, 0.006}));
    EXPECT_EQ(logTicks(0.08, 30.0), (std::vector<double>{0.1, 0.2, 0.5, 1, 2, 5, 10, 20}));
    EXPECT_TRUE(logTicks(0.0, 1.0).empty());
    EXPECT_TRUE(logTicks(2.0, 1.0).empty());
    Figure figure = sampleFigure();
    figure.panels[0].y.log = true;  // 25 to 40: [20:50]
    const std::string script = gnuplotScript(figure, "out.png");
    EXPECT_THAT(script, HasSubstr("set ytics (20, 30, 40, 50)\nset format y '%g'"));
    EXPECT_THAT(script, HasSubstr("set xtics autofreq"));
}

TEST(PlotScript, ASharedLegendSitsInAStripAtTheRight) {
    Figure figure = sampleFigure();
    figure.panels.push_back(figure.panels[0]);
    figure.width = 1000;
    figure.legendWidth = 300;
    figure.note = "#1 is exact";
    const std::string script = gnuplotScript(figure, "out.png");
    // Panels end at 0.97 - 300 / 1000 of the width; the key starts at 1 - 0.3.
    EXPECT_THAT(script, HasSubstr("set multiplot layout 1,2 margins 0.07, 0.67, 0.12, 0.92"));
    EXPECT_EQ(count(script, "unset key"), 1u);  // the first panel
    EXPECT_THAT(script, HasSubstr("set key at screen 0.7, 0.92"));
    EXPECT_THAT(script, HasSubstr("set label 1 '#1 is exact' at screen 0.7, 0.04"));
    figure.legendWidth = 600;
    EXPECT_THAT([&] { checkFigure(figure, "f.png"); },
                ::testing::ThrowsMessage<Error>(HasSubstr("expected a legend strip of 0 to half the plot's width")));
}

// gnuplot sizes the key's box at about 9 pixels a character cell for the longest title plus 7
// cells, wider than the text: the box is narrowed to the strip instead of running off the figure.
TEST(PlotScript, ASharedLegendsBoxIsNarrowedToItsStrip) {
    Figure figure = sampleFigure();
    figure.panels.push_back(figure.panels[0]);
    figure.width = 1600;
    figure.legendWidth = 480;
    // The longest title (the best alternative's) has 53 characters: 60 cells; the strip holds
    // (480 - 18) / 9 = 51.
    EXPECT_THAT(gnuplotScript(figure, "out.png"),
                HasSubstr("set key at screen 0.7, 0.92 left top Left reverse box width -9\n"));
    figure.legendWidth = 700;  // 75 cells
    EXPECT_THAT(gnuplotScript(figure, "out.png"), Not(HasSubstr(" width ")));
}

// A top view: two cells as filled polygons, a wall as an open path; metres equal on both axes
// and +z (y here) growing downwards.
TEST(PlotScript, ShapesAreDrawnOneByOneAndPolygonsClosed) {
    PlotPanel panel;
    panel.title = "plan";
    panel.x = {"x", "m", false};
    panel.y = {"z", "m", false, false, true};
    panel.equalScale = true;
    panel.series = {{"cells", {}, SeriesStyle::Filled, {{{0, 0}, {2, 0}, {2, 2}}, {{3, 3}, {5, 3}, {5, 5}}}, "#00a000"},
                    {.name = "walls", .style = SeriesStyle::Paths, .shapes = {{{0, 0}, {0, 5}}}}};
    Figure figure;
    figure.panels = {panel};
    const std::string script = gnuplotScript(figure, "plan.png");
    // Each polygon repeats its first vertex and ends with a blank line; the path does not close.
    EXPECT_THAT(script, HasSubstr("$p0_s0 << EOD\n0 0\n2 0\n2 2\n0 0\n\n3 3\n5 3\n5 5\n3 3\n\nEOD\n"));
    EXPECT_THAT(script, HasSubstr("$p0_s1 << EOD\n0 0\n0 5\n\nEOD\n"));
    EXPECT_THAT(script, HasSubstr("with filledcurves closed fs transparent solid 0.45 noborder lc rgb '#00a000'"));
    EXPECT_THAT(script, HasSubstr("$p0_s1 using 1:2 with lines"));
    EXPECT_THAT(script, HasSubstr("set size ratio -1"));
    // z from 0 to 5 with 0.4 m margins, listed from the larger end: +z grows downwards.
    EXPECT_THAT(script, HasSubstr("set yrange [5.4:-0.4]"));
    EXPECT_THAT(script, HasSubstr("set xlabel 'x (m)'"));
}

TEST(PlotScript, PanelsFillAGridRowByRow) {
    Figure figure = sampleFigure();
    figure.panels = {figure.panels[0], figure.panels[0], figure.panels[0]};
    figure.columns = 2;
    EXPECT_THAT(gnuplotScript(figure, "out.png"), HasSubstr("set multiplot layout 2,2\n"));
}

TEST(PlotScript, ColoursMustBeHexTriples) {
    Figure figure = sampleFigure();
    figure.panels[0].series[0].colour = "red' lw 9";  // would break out of the quotes
    EXPECT_THAT([&] { checkFigure(figure, "f.png"); },
                ::testing::ThrowsMessage<Error>(HasSubstr(
                    "f.png: panel 1 'Pooled PSNR against frame time': series 'walls a=10 blend': expected a colour "
                    "\"#rrggbb\", got 'red' lw 9'")));
    figure.panels[0].series[0].colour = "#A0b0C0";
    EXPECT_NO_THROW(checkFigure(figure, "f.png"));
}

TEST(PlotScript, APanelWithoutPointsSaysSo) {
    Figure figure = sampleFigure();
    figure.panels[0].series.clear();
    const std::string script = gnuplotScript(figure, "out.png");
    EXPECT_THAT(script, HasSubstr("set xrange [0:1]"));
    EXPECT_THAT(script, HasSubstr("'no data'"));
}

TEST(PlotScript, SeveralPanelsSitSideBySide) {
    Figure figure = sampleFigure();
    figure.panels.push_back(figure.panels[0]);
    figure.panels[1].title = "FLIP";
    const std::string script = gnuplotScript(figure, "out.png");
    EXPECT_THAT(script, HasSubstr("set multiplot layout 1,2"));
    EXPECT_THAT(script, HasSubstr("$p1_front"));
    EXPECT_EQ(count(script, "\nplot "), 2u);
}

// Arrows go to gnuplot as tail and step ("x y dx dy"), labels as text at a point, placed by
// their anchor, and removed after their panel so that the next panel does not show them.
TEST(PlotScript, ArrowsAreTailAndStepAndLabelsSitAtTheirPoints) {
    PlotPanel panel;
    panel.title = "display";
    panel.x = {"x", "m", false};
    panel.y = {"z", "m", false};
    panel.series = {{"normal", {}, SeriesStyle::Arrows, {{{1, 2}, {1.5, 1}}}, "#303030"}};
    panel.labels = {{"front", 0.5, -1.5}, {"it's left", -1, 0, LabelAnchor::Right}};
    Figure figure;
    figure.panels = {panel, panel};
    const std::string script = gnuplotScript(figure, "display.png");
    EXPECT_THAT(script, HasSubstr("$p0_s0 << EOD\n1 2 0.5 -1\nEOD\n"));
    EXPECT_THAT(script, HasSubstr("$p0_s0 using 1:2:3:4 with vectors head filled"));
    EXPECT_THAT(script, HasSubstr("set label 100 'front' at 0.5, -1.5 center front\n"));
    figure.panels[0].series.push_back({"fill", {}, SeriesStyle::Filled, {{{0, 0}, {1, 0}, {1, 1}}}, "", 0.0, 0.2});
    EXPECT_THAT(gnuplotScript(figure, "display.png"), HasSubstr("fs transparent solid 0.2 noborder"));
    figure.panels[0].series.back().opacity = 0.0;
    EXPECT_THAT([&] { checkFigure(figure, "display.png"); },
                ::testing::ThrowsMessage<Error>(HasSubstr("'fill': expected an opacity in (0, 1], got 0")));
    figure.panels[0].series.pop_back();
    EXPECT_THAT(script, HasSubstr("set label 101 'it''s left' at -1, 0 left offset char 0.6, 0 front\n"));
    EXPECT_EQ(count(script, "unset label 100\n"), 2u);
    // The arrow's head counts in the range: x from 1 to 1.5 with 8 % margins.
    EXPECT_THAT(script, HasSubstr("set xrange [0.96:1.54]"));
    figure.panels[1].labels[0].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { checkFigure(figure, "display.png"); },
                ::testing::ThrowsMessage<Error>(HasSubstr(
                    "display.png: panel 2 'display': label 'front': expected finite x and y, got x=0.5 y=nan")));
}

TEST(PlotScript, NonFinitePointsAreRefusedWithWhereAndWhat) {
    Figure figure = sampleFigure();
    figure.panels[0].series[2].points[0].y = std::numeric_limits<double>::quiet_NaN();
    EXPECT_THAT([&] { gnuplotScript(figure, "bench.png"); },
                ::testing::ThrowsMessage<Error>(
                    HasSubstr("bench.png: panel 1 'Pooled PSNR against frame time': series 'full lod 1px': point 1: "
                              "expected finite x and y, got x=9 y=nan")));
    figure.panels[0].series[2].points[0].y = 1.0;
    figure.panels[0].series[0].points[0].x = std::numeric_limits<double>::infinity();
    EXPECT_THAT(
        [&] { checkFigure(figure, "f.png"); },
        ::testing::ThrowsMessage<Error>(HasSubstr("'walls a=10 blend': point 1: expected finite x and y, got x=inf")));
}

TEST(PlotScript, EmptyFiguresAndTinySizesAreRefused) {
    EXPECT_THAT([] { checkFigure(Figure{}, "a.png"); },
                ::testing::ThrowsMessage<Error>(HasSubstr("a.png: expected at least one plot panel, got none")));
    Figure figure = sampleFigure();
    figure.width = 100;
    EXPECT_THAT(
        [&] { checkFigure(figure, "a.png"); },
        ::testing::ThrowsMessage<Error>(HasSubstr("expected a plot of at least 160 x 120 pixels, got 100 x 320")));
}

TEST(Gnuplot, FindsProgramsOnASearchPath) {
    const test::TempFolder folder("gnuplot_find");
    const std::filesystem::path fake = folder / "gnuplot";
    std::ofstream(fake) << "#!/bin/sh\n";
    EXPECT_TRUE(findProgram("gnuplot", folder.path().string()).empty());  // not executable yet
    std::filesystem::permissions(fake, std::filesystem::perms::owner_all);
    EXPECT_EQ(findProgram("gnuplot", "/nonexistent:" + folder.path().string()), fake);
}

TEST(Gnuplot, AMissingGnuplotSaysWhatToInstallAndWhereItLooked) {
    const test::TempFolder folder("gnuplot_missing");
    const GnuplotOptions options{folder.path().string() + ":/nonexistent"};
    EXPECT_THAT([&] { requireGnuplot(options); },
                ::testing::ThrowsMessage<Error>(HasSubstr("gnuplot not found: install gnuplot-nox (searched PATH: " +
                                                          folder.path().string() + ":/nonexistent)")));
    EXPECT_THAT([&] { writePlot(folder / "p.png", sampleFigure(), options); },
                ::testing::ThrowsMessage<Error>(HasSubstr("gnuplot not found")));
    EXPECT_FALSE(std::filesystem::exists(folder / "p.png"));
}

// Runs the real gnuplot: a PNG of the figure's size comes out, with text and markers (more than
// one colour), and no temporary file is left beside it.
TEST(Gnuplot, WritesAPngOfTheStatedSize) {
    const test::TempFolder folder("gnuplot_png");
    const std::filesystem::path png = folder / "plot.png";
    writePlot(png, sampleFigure());
    const scenes::Image image = scenes::readImage(png);
    EXPECT_EQ(image.width, 480);
    EXPECT_EQ(image.height, 320);
    std::size_t dark = 0, coloured = 0;
    for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
        const int r = image.rgba[i], g = image.rgba[i + 1], b = image.rgba[i + 2];
        dark += r < 64 && g < 64 && b < 64;                        // text, axes, rings
        coloured += std::abs(r - g) > 60 || std::abs(g - b) > 60;  // the series' markers
    }
    EXPECT_GT(dark, 500u);
    EXPECT_GT(coloured, 50u);
    std::size_t files = 0;
    for ([[maybe_unused]] const auto& entry : std::filesystem::directory_iterator(folder.path())) ++files;
    EXPECT_EQ(files, 1u);
}

// A script gnuplot refuses (here: a file where the PNG's folder should be) is an Error naming
// the PNG with gnuplot's status, and the old file stays.
TEST(Gnuplot, AFailedRunIsAnErrorAndKeepsTheOldFile) {
    const test::TempFolder folder("gnuplot_fail");
    const std::filesystem::path png = folder / "plot.png";
    std::ofstream(png) << "old";
    const test::TempFolder bin("gnuplot_fail_bin");
    std::ofstream(bin / "gnuplot") << "#!/bin/sh\necho 'line 1: undefined variable: x' >&2\nexit 1\n";
    std::filesystem::permissions(bin / "gnuplot", std::filesystem::perms::owner_all);
    EXPECT_THAT([&] { writePlot(png, sampleFigure(), {bin.path().string()}); },
                ::testing::ThrowsMessage<Error>(HasSubstr("plot.png: " + (bin / "gnuplot").string() +
                                                          " exited with status 1: line 1: undefined variable: x")));
    std::ifstream in(png);
    std::string text;
    in >> text;
    EXPECT_EQ(text, "old");
}

}  // namespace
}  // namespace cavewall::bench
