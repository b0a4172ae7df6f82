#include "app/bench/plot.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

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

// One inline data block, "$name << EOD", x y per line, "EOD".
std::string dataBlock(const std::string& name, const std::vector<PlotPoint>& points) {
    std::string out = name + " << EOD\n";
    for (const PlotPoint& p : points) out += number(p.x) + " " + number(p.y) + "\n";
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

// Everything one panel's plot command needs: its data blocks and the comma-separated plot items.
struct PanelPlot {
    std::string blocks;
    std::vector<std::string> items;
};

PanelPlot panelPlot(const PlotPanel& panel, std::size_t index) {
    PanelPlot out;
    const std::string prefix = "$p" + std::to_string(index) + "_";
    int shown = 0;
    for (std::size_t i = 0; i < panel.series.size(); ++i) {
        const PlotSeries& s = panel.series[i];
        if (s.points.empty()) continue;
        const std::string block = prefix + "s" + std::to_string(i);
        out.blocks += dataBlock(block, s.line ? sortedByX(s.points) : s.points);
        out.items.push_back(block + " using 1:2 with " + (s.line ? "linespoints lw 2" : "points") + " pt " +
                            std::to_string(kMarkers[shown % 6]) + " ps 1.4 lc rgb '" + kColours[shown % 8] +
                            "' title " + gnuplotQuoted(s.name));
        ++shown;
    }
    struct Overlay {
        bool PlotPoint::*flag;
        const char* block;
        const char* style;
        const std::string* name;
    };
    const Overlay overlays[] = {
        {&PlotPoint::front, "front", "lines dt 2 lw 2 lc rgb '#404040'", &panel.frontName},
        {&PlotPoint::control, "control", "points pt 6 ps 3.5 lw 2 lc rgb '#000000'", &panel.controlName},
        {&PlotPoint::bestAlternative, "alternative", "points pt 4 ps 3.5 lw 2 lc rgb '#000000'",
         &panel.alternativeName}};
    for (const Overlay& o : overlays) {
        const std::vector<PlotPoint> points = flagged(panel, o.flag);
        if (points.empty()) continue;
        out.blocks += dataBlock(prefix + o.block, points);
        out.items.push_back(prefix + o.block + " using 1:2 with " + o.style + " title " + gnuplotQuoted(*o.name));
    }
    return out;
}

// The axis range of every point's `coordinate` with 8 % of the span as a margin beyond the
// extremes, so that no marker sits on the frame; from 0 when `axis.fromZero`.
std::string axisRange(const PlotPanel& panel, const PlotAxis& axis, double PlotPoint::*coordinate) {
    double lo = INFINITY, hi = -INFINITY;
    for (const PlotSeries& s : panel.series)
        for (const PlotPoint& p : s.points) {
            lo = std::min(lo, p.*coordinate);
            hi = std::max(hi, p.*coordinate);
        }
    if (lo > hi) return "[0:1]";
    if (axis.fromZero) lo = std::min(lo, 0.0);
    double span = hi - lo;
    if (span <= 0.0) span = hi != 0.0 ? std::abs(hi) * 0.2 : 1.0;
    const double margin = 0.08 * span;
    return "[" + number(axis.fromZero && lo >= 0.0 ? 0.0 : lo - margin) + ":" + number(hi + margin) + "]";
}

// Title, axes, grid and legend of one panel, then its plot command.
std::string panelCommands(const PlotPanel& panel, const PanelPlot& plot) {
    std::string out = "set title " + gnuplotQuoted(panel.title) + "\n";
    out += "set xlabel " + gnuplotQuoted(axisLabel(panel.x)) + "\n";
    out += "set ylabel " + gnuplotQuoted(axisLabel(panel.y)) + "\n";
    out += "set xrange " + axisRange(panel, panel.x, &PlotPoint::x) + "\n";
    out += "set yrange " + axisRange(panel, panel.y, &PlotPoint::y) + "\n";
    // The key's extra height keeps its box off the x axis title.
    out += "set grid\nset key below left Left reverse maxrows 8 box height 1.5\n";
    if (plot.items.empty())
        return out + "set label 1 'no data' at graph 0.5, 0.5 center\nplot NaN notitle\nunset label 1\n";
    out += "plot ";
    for (std::size_t i = 0; i < plot.items.size(); ++i) out += (i ? ", \\\n     " : "") + plot.items[i];
    return out + "\n";
}

}  // namespace

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
    for (std::size_t p = 0; p < figure.panels.size(); ++p)
        for (const PlotSeries& s : figure.panels[p].series)
            for (std::size_t i = 0; i < s.points.size(); ++i)
                if (!std::isfinite(s.points[i].x) || !std::isfinite(s.points[i].y))
                    throw Error(where + ": panel " + std::to_string(p + 1) + " '" + figure.panels[p].title +
                                "': series '" + s.name + "': point " + std::to_string(i + 1) +
                                ": expected finite x and y, got " + pointText(s.points[i]));
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
    script << "set multiplot layout 1," << figure.panels.size() << "\n";
    for (std::size_t i = 0; i < figure.panels.size(); ++i) script << panelCommands(figure.panels[i], plots[i]);
    script << "unset multiplot\nset output\n";
    return script.str();
}

}  // namespace cavewall::bench
