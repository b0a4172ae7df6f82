#pragma once
// Plots as plain data, and the gnuplot script that draws them. A Figure is one PNG of one or
// more panels in a grid; a Panel has a title, two titled axes with units and named series,
// each named in the legend: markers, lines, shapes (open paths, polygon outlines, filled
// polygons; for top views in metres) or arrows, and text labels at data coordinates. Points
// may be flagged as on the Pareto front (joined by one line in x order across all series of the
// panel), as the control, as the best alternative or as recommended (each ringed by a large
// marker with its own legend entry). No GL, no files: gnuplotScript() returns the text;
// app/bench/gnuplot.h runs it.

#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::bench {

struct PlotPoint {
    double x = 0.0, y = 0.0;       // finite (checkFigure refuses NaN and infinities)
    bool front = false;            // on the Pareto front
    bool control = false;          // the control (the "cells without textures" mode)
    bool bestAlternative = false;  // the alternative a user would pick (full geometry with LOD)
    bool recommended = false;      // the recommended mode (app/bench/recommend.h)
};

// How a series is drawn.
enum class SeriesStyle {
    Markers,   // `points`, one marker each
    Line,      // `points` joined in x order, with markers (a series over a sweep)
    Paths,     // `shapes`, each an open polyline (a wall: its two ends)
    Outlines,  // `shapes`, each a closed polygon's outline
    Filled,    // `shapes`, each a closed polygon, filled half-transparent (`opacity`)
    Arrows,    // `shapes`, each {tail, head}: an arrow with a filled head (other points ignored)
};

struct PlotSeries {
    std::string name;                 // its legend entry; any text (quotes are escaped, line breaks become spaces)
    std::vector<PlotPoint> points{};  // Markers, Line
    SeriesStyle style = SeriesStyle::Markers;
    std::vector<std::vector<PlotPoint>> shapes{};  // Paths, Outlines, Filled, Arrows (flags unused)
    std::string colour{};   // "#rrggbb"; empty: a colour (and marker) chosen by the series' index
    double size = 0.0;      // marker size or line width, gnuplot units; 0: the style's default
    double opacity = 0.45;  // Filled: the fill's opacity, in (0, 1]
};

struct PlotAxis {
    std::string title;      // "median frame time"
    std::string unit;       // "ms"; shown as "median frame time (ms)"; empty: no unit (a ratio)
    bool fromZero = true;   // the range starts at 0; else it spans the data (8 % margins)
    bool log = false;       // logarithmic (every coordinate > 0; fromZero ignored)
    bool reversed = false;  // values grow leftwards or downwards (a top view's +z is down)
};

// Where a label's text sits relative to its point, as seen on the page (a reversed axis does not
// turn it round): on it, or half a character beside it on one side.
enum class LabelAnchor { Centre, Right, Left, Above, Below };

// Text drawn at a point of the panel, over the series; not in the legend and not counted in
// the axis ranges.
struct PlotLabel {
    std::string text;  // any text, quoted as series names are
    double x = 0.0, y = 0.0;
    LabelAnchor anchor = LabelAnchor::Centre;
};

struct PlotPanel {
    std::string title;
    PlotAxis x, y;
    std::vector<PlotSeries> series;          // in legend order; empty series are skipped
    std::vector<PlotLabel> labels;           // finite coordinates (checkFigure)
    std::string frontName = "Pareto front";  // legend entries of the flagged points' markers
    std::string controlName = "control";
    std::string alternativeName = "best alternative";
    std::string recommendedName = "recommended";
    bool equalScale = false;  // one unit as long on both axes (a floor plan in metres)
};

struct Figure {
    std::vector<PlotPanel> panels;   // at least one; left to right, then top to bottom
    int columns = 0;                 // panels per row; 0: all in one row
    int width = 1280, height = 560;  // PNG pixels, at least 160 x 120
    // > 0: one legend for all panels, the last panel's, in a strip this many pixels wide at the
    // right (panels listing the same series in the same order draw them alike); 0: a legend
    // below each panel. At most half the width.
    int legendWidth = 0;
    std::string note;  // a line under the shared legend (legendWidth > 0); empty: none
};

// "median frame time (ms)", or the title alone without a unit.
std::string axisLabel(const PlotAxis& axis);

// The tick values of a logarithmic axis from lo to hi (both > 0): 1, 2 and 5 times the powers of
// ten in the range, or 1, 1.5, 2, 3, 4, 5, 6 and 8 times them where that gives fewer than three
// (a range within one decade); ascending. Empty for a range that is not positive and finite.
std::vector<double> logTicks(double lo, double hi);

// Throws cavewall::Error naming `where` (the PNG), the panel, the series and the point when
// `figure` has no panel, a size under 160 x 120, a legend strip over half the width, a
// non-finite coordinate of a point or label ("bench.png: panel 1 'error': series 'walls a=10': point 2: expected
// finite x and y, got x=3 y=nan"), one <= 0 on a logarithmic axis, or a colour that is not
// "#rrggbb".
void checkFigure(const Figure& figure, const std::string& where);

// The gnuplot script that draws `figure` (checked first) with the pngcairo terminal into
// `output`: the data as inline data blocks, one plot command per panel. Strings are
// single-quoted with quotes doubled and enhanced-text markup off, so any name prints as given.
std::string gnuplotScript(const Figure& figure, const std::filesystem::path& output);

// `text` as a gnuplot single-quoted string: 'it''s'; line breaks become spaces.
std::string gnuplotQuoted(const std::string& text);

}  // namespace cavewall::bench
