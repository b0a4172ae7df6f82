#include "app/bench/plot.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>

namespace cavewall::bench {

namespace {

// Eight colours that stay apart in print and for common colour blindness (Okabe & Ito 2008),
// crossed with six filled marker shapes: 24 series before a pair repeats.
constexpr const char* kColours[] = {"#0072b2", "#d55e00", "#009e73", "#cc79a7",
                                    "#e69f00", "#56b4e9", "#000000", "#999933"};
constexpr int kMarkers[] = {7, 5, 9, 11, 13, 15};  // gnuplot: filled circle, square, triangles, diamond, pentagon

std::string number(double v) {
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.10g", v);
    return buffer;
}

std::string pointText(const PlotPoint& p) { return "x=" + number(p.x) + " y=" + number(p.y); }

bool drawsShapes(SeriesStyle style) {
    return style == SeriesStyle::Paths || style == SeriesStyle::Outlines || style == SeriesStyle::Filled ||
           style == SeriesStyle::Arrows;
}

// Every point of a series, markers and shape vertices alike.
std::vector<PlotPoint> allPoints(const PlotSeries& s) {
    std::vector<PlotPoint> out = s.points;
    for (const auto& shape : s.shapes) out.insert(out.end(), shape.begin(), shape.end());
    return out;
}

// One inline data block, "$name << EOD", x y per line, "EOD".
std::string dataBlock(const std::string& name, const std::vector<PlotPoint>& points) {
    std::string out = name + " << EOD\n";
    for (const PlotPoint& p : points) out += number(p.x) + " " + number(p.y) + "\n";
    return out + "EOD\n";
}

// Shapes as one data block, a blank line between shapes (gnuplot draws each on its own);
// closed shapes repeat their first vertex.
std::string shapesBlock(const std::string& name, const PlotSeries& s) {
    std::string out = name + " << EOD\n";
    for (const auto& shape : s.shapes) {
        if (shape.empty()) continue;
        for (const PlotPoint& p : shape) out += number(p.x) + " " + number(p.y) + "\n";
        if (s.style != SeriesStyle::Paths) out += number(shape[0].x) + " " + number(shape[0].y) + "\n";
        out += "\n";
    }
    return out + "EOD\n";
}

// Arrows as one data block of "x y dx dy" lines (gnuplot's `vectors`), tail to head.
std::string arrowsBlock(const std::string& name, const PlotSeries& s) {
    std::string out = name + " << EOD\n";
    for (const auto& shape : s.shapes) {
        if (shape.size() < 2) continue;
        out += number(shape[0].x) + " " + number(shape[0].y) + " " + number(shape[1].x - shape[0].x) + " " +
               number(shape[1].y - shape[0].y) + "\n";
    }
    return out + "EOD\n";
}

std::vector<PlotPoint> sortedByX(std::vector<PlotPoint> points) {
    std::sort(points.begin(), points.end(),
              [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
    return points;
}

// The panel's points whose flag `member` is set, from every series, in x order.
std::vector<PlotPoint> flagged(const PlotPanel& panel, bool PlotPoint::*member) {
    std::vector<PlotPoint> out;
    for (const PlotSeries& s : panel.series)
        for (const PlotPoint& p : s.points)
            if (p.*member) out.push_back(p);
    return sortedByX(out);
}

// The "with ..." part of series `index`'s plot item: style, marker, size and colour.
std::string seriesStyle(const PlotSeries& s, std::size_t index) {
    const std::string colour = " lc rgb '" + (s.colour.empty() ? std::string(kColours[index % 8]) : s.colour) + "'";
    const auto size = [&](double fallback) { return number(s.size > 0.0 ? s.size : fallback); };
    const std::string marker = " pt " + std::to_string(kMarkers[index % 6]);
    switch (s.style) {
        case SeriesStyle::Markers: return "points" + marker + " ps " + size(1.4) + colour;
        case SeriesStyle::Line: return "linespoints lw " + size(2) + marker + " ps 1.4" + colour;
        case SeriesStyle::Paths:
        case SeriesStyle::Outlines: return "lines lw " + size(1.5) + colour;
        case SeriesStyle::Filled:
            return "filledcurves closed fs transparent solid " + number(s.opacity) + " noborder" + colour;
        case SeriesStyle::Arrows: return "vectors head filled size screen 0.012,25 lw " + size(1.5) + colour;
    }
    return "points" + colour;
}

// Everything one panel's plot command needs: its data blocks and the comma-separated plot items.
struct PanelPlot {
    std::string blocks;
    std::vector<std::string> items;
    std::size_t longestTitle = 0;  // characters

    void add(const std::string& item, const std::string& title) {
        items.push_back(item + " title " + gnuplotQuoted(title));
        // UTF-8: count the bytes that start a character.
        const auto chars = std::count_if(title.begin(), title.end(), [](char c) { return (c & 0xC0) != 0x80; });
        longestTitle = std::max(longestTitle, static_cast<std::size_t>(chars));
    }
};

// The large markers over the flagged points, and the front's line, with their legend entries.
void addOverlays(const PlotPanel& panel, const std::string& prefix, PanelPlot& out) {
    struct Overlay {
        bool PlotPoint::*flag;
        const char* block;
        const char* style;
        const std::string* name;
    };
    const Overlay overlays[] = {
        {&PlotPoint::front, "front", "lines dt 2 lw 2 lc rgb '#404040'", &panel.frontName},
        {&PlotPoint::control, "control", "points pt 6 ps 3 lw 2 lc rgb '#000000'", &panel.controlName},
        {&PlotPoint::bestAlternative, "alternative", "points pt 4 ps 3 lw 2 lc rgb '#000000'", &panel.alternativeName},
        {&PlotPoint::recommended, "recommended", "points pt 12 ps 3.5 lw 2 lc rgb '#c00000'", &panel.recommendedName}};
    for (const Overlay& o : overlays) {
        const std::vector<PlotPoint> points = flagged(panel, o.flag);
        if (points.empty()) continue;
        out.blocks += dataBlock(prefix + o.block, points);
        out.add(prefix + o.block + " using 1:2 with " + o.style, *o.name);
    }
}

PanelPlot panelPlot(const PlotPanel& panel, std::size_t index) {
    PanelPlot out;
    const std::string prefix = "$p" + std::to_string(index) + "_";
    // Styles follow the series' index, so that panels listing the same series in the same order
    // draw each one alike even where one panel has no point of it.
    for (std::size_t i = 0; i < panel.series.size(); ++i) {
        const PlotSeries& s = panel.series[i];
        if (allPoints(s).empty()) continue;
        const std::string block = prefix + "s" + std::to_string(i);
        out.blocks += s.style == SeriesStyle::Arrows ? arrowsBlock(block, s)
                      : drawsShapes(s.style)         ? shapesBlock(block, s)
                      : s.style == SeriesStyle::Line ? dataBlock(block, sortedByX(s.points))
                                                     : dataBlock(block, s.points);
        const char* columns = s.style == SeriesStyle::Arrows ? " using 1:2:3:4" : " using 1:2";
        out.add(block + columns + " with " + seriesStyle(s, i), s.name);
    }
    addOverlays(panel, prefix, out);
    return out;
}

// The ends of the axis range of every point's `coordinate` (low, high), with 8 % of the span
// as a margin beyond the extremes, so that no marker sits on the frame; from 0 when
// `axis.fromZero`; a factor of 1.25 beyond them on a logarithmic axis.
std::pair<double, double> axisEnds(const PlotPanel& panel, const PlotAxis& axis, double PlotPoint::*coordinate) {
    double lo = INFINITY, hi = -INFINITY;
    for (const PlotSeries& s : panel.series)
        for (const PlotPoint& p : allPoints(s)) {
            lo = std::min(lo, p.*coordinate);
            hi = std::max(hi, p.*coordinate);
        }
    if (lo > hi) return {axis.log ? 0.1 : 0.0, 1.0};
    if (axis.log) return {lo / 1.25, hi * 1.25};
    if (axis.fromZero) lo = std::min(lo, 0.0);
    double span = hi - lo;
    if (span <= 0.0) span = hi != 0.0 ? std::abs(hi) * 0.2 : 1.0;
    const double margin = 0.08 * span;
    return {axis.fromZero && lo >= 0.0 ? 0.0 : lo - margin, hi + margin};
}

// The range command's brackets; reversed axes list the ends the other way round.
std::string axisRange(std::pair<double, double> ends, const PlotAxis& axis) {
    const auto [lo, hi] = ends;
    return axis.reversed ? "[" + number(hi) + ":" + number(lo) + "]" : "[" + number(lo) + ":" + number(hi) + "]";
}

// The tick marks of one axis. gnuplot labels a logarithmic axis at powers of ten only, so a
// range within one decade (FLIP means of 0.003 to 0.009) would carry no number at all: such an
// axis gets its ticks at 1, 2 and 5 times a power of ten, or at finer steps where those give
// fewer than three, written in %g. A linear axis keeps gnuplot's own.
std::string ticCommands(std::pair<double, double> ends, const PlotAxis& axis, const char* name) {
    const std::string automatic = std::string("set ") + name + "tics autofreq\nset format " + name + " '% h'\n";
    if (!axis.log) return automatic;
    const std::vector<double> ticks = logTicks(ends.first, ends.second);
    if (ticks.size() < 2) return automatic;
    std::string out = std::string("set ") + name + "tics (";
    for (std::size_t i = 0; i < ticks.size(); ++i) out += (i ? ", " : "") + number(ticks[i]);
    return out + ")\nset format " + name + " '%g'\n";
}

// gnuplot sizes a key's box in character cells, about 9 pixels each in the figure's font, for
// the longest title plus about 7 cells of sample and spacing; the text itself is narrower
// (about 8 pixels a character).
constexpr int kKeyCellPixels = 9, kKeyExtraCells = 7;

// The legend of panel `index`: its own below it, or the figure's shared one (the last panel's,
// in the strip at the right), with the figure's note under it. A shared legend's box is
// narrowed to its strip where gnuplot's estimate of a long title would run past the figure's
// right edge.
std::string keyCommands(const Figure& figure, std::size_t index, std::size_t longestTitle) {
    // The key's extra height keeps its box off the x axis title.
    if (figure.legendWidth <= 0) return "set key below left Left reverse maxrows 8 box height 1.5\n";
    if (index + 1 < figure.panels.size()) return "unset key\n";
    const std::string left = number(1.0 - static_cast<double>(figure.legendWidth) / figure.width);  // strip start
    const int cells = static_cast<int>(longestTitle) + kKeyExtraCells;
    const int fits = (figure.legendWidth - 2 * kKeyCellPixels) / kKeyCellPixels;
    const std::string width = cells > fits ? " width " + std::to_string(fits - cells) : "";
    std::string out = "set key at screen " + left + ", 0.92 left top Left reverse box" + width + "\n";
    if (!figure.note.empty())
        out += "set label 1 " + gnuplotQuoted(figure.note) + " at screen " + left + ", 0.04 left\n";
    return out;
}

// The range, scale and title of one axis ("x" or "y").
std::string axisCommands(const PlotPanel& panel, const PlotAxis& axis, const char* name,
                         double PlotPoint::*coordinate) {
    const std::pair<double, double> ends = axisEnds(panel, axis, coordinate);
    return std::string(axis.log ? "set logscale " : "unset logscale ") + name + "\nset " + name + "label " +
           gnuplotQuoted(axisLabel(axis)) + "\nset " + name + "range " + axisRange(ends, axis) + "\n" +
           ticCommands(ends, axis, name);
}

// The panel's text labels (tags from kFirstLabel on, so that they never replace the note's or
// the "no data" label) and the commands that remove them after its plot.
constexpr std::size_t kFirstLabel = 100;

// gnuplot's justification and offset (in characters) for an anchor.
const char* anchorPlacement(LabelAnchor anchor) {
    switch (anchor) {
        case LabelAnchor::Centre: return "center";
        case LabelAnchor::Right: return "left offset char 0.6, 0";
        case LabelAnchor::Left: return "right offset char -0.6, 0";
        case LabelAnchor::Above: return "center offset char 0, 0.9";
        case LabelAnchor::Below: return "center offset char 0, -0.9";
    }
    return "center";
}

std::string labelCommands(const PlotPanel& panel) {
    std::string out;
    for (std::size_t i = 0; i < panel.labels.size(); ++i) {
        const PlotLabel& l = panel.labels[i];
        out += "set label " + std::to_string(kFirstLabel + i) + " " + gnuplotQuoted(l.text) + " at " + number(l.x) +
               ", " + number(l.y) + " " + anchorPlacement(l.anchor) + " front\n";
    }
    return out;
}

std::string unsetLabelCommands(const PlotPanel& panel) {
    std::string out;
    for (std::size_t i = 0; i < panel.labels.size(); ++i)
        out += "unset label " + std::to_string(kFirstLabel + i) + "\n";
    return out;
}

// Title, axes, grid, labels and legend of one panel, then its plot command.
std::string panelCommands(const Figure& figure, std::size_t index, const PanelPlot& plot) {
    const PlotPanel& panel = figure.panels[index];
    std::string out = "set title " + gnuplotQuoted(panel.title) + "\n";
    out += axisCommands(panel, panel.x, "x", &PlotPoint::x) + axisCommands(panel, panel.y, "y", &PlotPoint::y);
    out += panel.equalScale ? "set size ratio -1\n" : "set size noratio\n";
    out += "set grid\n" + keyCommands(figure, index, plot.longestTitle) + labelCommands(panel);
    if (plot.items.empty())
        return out + "set label 2 'no data' at graph 0.5, 0.5 center\nplot NaN notitle\nunset label 2\n" +
               unsetLabelCommands(panel);
    out += "plot ";
    for (std::size_t i = 0; i < plot.items.size(); ++i) out += (i ? ", \\\n     " : "") + plot.items[i];
    return out + "\n" + unsetLabelCommands(panel);
}

// The multiplot layout: rows and columns, and with a shared legend the panels' area left of its
// strip (screen fractions).
std::string layoutCommand(const Figure& figure) {
    const std::size_t panels = figure.panels.size();
    const std::size_t columns = figure.columns > 0 ? std::min<std::size_t>(figure.columns, panels) : panels;
    const std::size_t rows = (panels + columns - 1) / columns;
    std::string out = "set multiplot layout " + std::to_string(rows) + "," + std::to_string(columns);
    if (figure.legendWidth > 0)
        out += " margins 0.07, " + number(0.97 - static_cast<double>(figure.legendWidth) / figure.width) +
               ", 0.12, 0.92 spacing 0.08";
    return out + "\n";
}

bool isColour(const std::string& text) {
    return text.size() == 7 && text[0] == '#' &&
           text.find_first_not_of("0123456789abcdefABCDEF", 1) == std::string::npos;
}

// Throws for the first bad point or colour of series `s` in panel `p` (1-based in messages).
void checkSeries(const PlotPanel& panel, std::size_t p, const PlotSeries& s, const std::string& where) {
    const std::string at =
        where + ": panel " + std::to_string(p + 1) + " '" + panel.title + "': series '" + s.name + "'";
    if (!s.colour.empty() && !isColour(s.colour))
        throw Error(at + ": expected a colour \"#rrggbb\", got '" + s.colour + "'");
    if (!(s.opacity > 0.0 && s.opacity <= 1.0))
        throw Error(at + ": expected an opacity in (0, 1], got " + number(s.opacity));
    const std::vector<PlotPoint> points = allPoints(s);
    for (std::size_t i = 0; i < points.size(); ++i) {
        const PlotPoint& q = points[i];
        if (!std::isfinite(q.x) || !std::isfinite(q.y))
            throw Error(at + ": point " + std::to_string(i + 1) + ": expected finite x and y, got " + pointText(q));
        if ((panel.x.log && q.x <= 0.0) || (panel.y.log && q.y <= 0.0))
            throw Error(at + ": point " + std::to_string(i + 1) + ": expected x and y > 0 on a logarithmic axis, got " +
                        pointText(q));
    }
}

// Throws for the first label of panel `p` with a non-finite coordinate.
void checkLabels(const PlotPanel& panel, std::size_t p, const std::string& where) {
    for (const PlotLabel& l : panel.labels)
        if (!std::isfinite(l.x) || !std::isfinite(l.y))
            throw Error(where + ": panel " + std::to_string(p + 1) + " '" + panel.title + "': label '" + l.text +
                        "': expected finite x and y, got " + pointText({l.x, l.y}));
}

}  // namespace

std::vector<double> logTicks(double lo, double hi) {
    std::vector<double> out;
    if (!(lo > 0.0) || !(hi > lo) || !std::isfinite(hi)) return out;
    for (const std::vector<double>& steps :
         {std::vector<double>{1, 2, 5}, std::vector<double>{1, 1.5, 2, 3, 4, 5, 6, 8}}) {
        out.clear();
        for (int e = static_cast<int>(std::floor(std::log10(lo))); e <= static_cast<int>(std::ceil(std::log10(hi)));
             ++e)
            for (double m : steps) {
                const double v = m * std::pow(10.0, e);
                if (v >= lo && v <= hi) out.push_back(v);
            }
        if (out.size() >= 3) return out;
    }
    return out;
}

std::string axisLabel(const PlotAxis& axis) {
    return axis.unit.empty() ? axis.title : axis.title + " (" + axis.unit + ")";
}

std::string gnuplotQuoted(const std::string& text) {
    std::string out = "'";
    for (char c : text) {
        if (c == '\'')
            out += "''";
        else if (c == '\n' || c == '\r')
            out += ' ';
        else
            out += c;
    }
    return out + "'";
}

void checkFigure(const Figure& figure, const std::string& where) {
    if (figure.panels.empty()) throw Error(where + ": expected at least one plot panel, got none");
    if (figure.width < 160 || figure.height < 120)
        throw Error(where + ": expected a plot of at least 160 x 120 pixels, got " + std::to_string(figure.width) +
                    " x " + std::to_string(figure.height));
    if (figure.legendWidth < 0 || figure.legendWidth > figure.width / 2)
        throw Error(where + ": expected a legend strip of 0 to half the plot's width (" +
                    std::to_string(figure.width / 2) + " pixels), got " + std::to_string(figure.legendWidth));
    for (std::size_t p = 0; p < figure.panels.size(); ++p) {
        for (const PlotSeries& s : figure.panels[p].series) checkSeries(figure.panels[p], p, s, where);
        checkLabels(figure.panels[p], p, where);
    }
}

std::string gnuplotScript(const Figure& figure, const std::filesystem::path& output) {
    checkFigure(figure, output.filename().string());
    std::ostringstream script;
    script << "set terminal pngcairo size " << figure.width << "," << figure.height
           << " noenhanced font 'Sans,11' background rgb 'white'\n"
           << "set encoding utf8\nset output " << gnuplotQuoted(output.string()) << "\n";
    std::vector<PanelPlot> plots;
    for (std::size_t i = 0; i < figure.panels.size(); ++i) {
        plots.push_back(panelPlot(figure.panels[i], i));
        script << plots.back().blocks;
    }
    script << layoutCommand(figure);
    for (std::size_t i = 0; i < figure.panels.size(); ++i) script << panelCommands(figure, i, plots[i]);
    script << "unset multiplot\nset output\n";
    return script.str();
}

}  // namespace cavewall::bench
