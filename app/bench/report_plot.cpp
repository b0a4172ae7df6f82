#include "app/bench/report_plot.h"

#include <cmath>

namespace cavewall::bench {

namespace {

struct ErrorAxis {
    PlotAxis axis;
    double (*value)(const ModeResult&);  // the plotted figure
    double (*rank)(const ModeResult&);   // lower is better: the Pareto front's error
};

// One panel: every mode as its own series (so both panels style a mode alike), with a point
// where its time and figure are finite and the figure > 0 (FLIP is drawn on a logarithmic
// axis), and the front over those points.
PlotPanel errorPanel(const BenchReport& report, const std::string& title, const ErrorAxis& error) {
    PlotPanel panel;
    panel.title = title;
    panel.x = {"median frame time, all screens", "ms", true};
    panel.y = error.axis;
    panel.controlName = "control: cells without textures";
    panel.alternativeName = "best alternative: full geometry with levels of detail";
    panel.recommendedName = "recommended walls mode";
    const ModeResult* control = controlMode(report);
    const ModeResult* alternative = lodBaseline(report);
    // The control at the alternative's tolerance too, where the bench ran one.
    const ModeResult* lodControl = alternative ? controlFor(report, *alternative) : nullptr;
    std::vector<TradeOff> tradeOffs;
    std::vector<std::size_t> drawn;  // the series of each trade-off point
    for (std::size_t i = 0; i < report.modes.size(); ++i) {
        const ModeResult& m = report.modes[i];
        const double x = m.frameMs.p50, y = error.value(m);
        const bool compared = m.error.frames > 0 || i == 0;  // the reference compares with itself
        PlotSeries series;
        series.name = "#" + std::to_string(i + 1) + " " + modeLabel(m);
        panel.series.push_back(std::move(series));
        if (!compared || !std::isfinite(x) || !std::isfinite(y) || y <= 0.0) continue;
        panel.series.back().points = {
            {x, y, false, &m == control || &m == lodControl, &m == alternative, report.recommended == i}};
        tradeOffs.push_back({x, error.rank(m)});
        drawn.push_back(i);
    }
    for (std::size_t i : paretoFront(tradeOffs)) panel.series[drawn[i]].points[0].front = true;
    return panel;
}

}  // namespace

Figure tradeOffFigure(const BenchReport& report) {
    const ErrorAxis psnr{{"pooled PSNR", "dB", false},
                         [](const ModeResult& m) { return m.error.psnrDb; },
                         [](const ModeResult& m) { return m.error.rmse; }};
    const ErrorAxis flip{{"LDR-FLIP mean, logarithmic", "", false, true},
                         [](const ModeResult& m) { return m.error.flipMean; },
                         [](const ModeResult& m) { return m.error.flipMean; }};
    const std::string suffix = report.resolution.empty() ? "" : " (" + report.resolution + ")";
    Figure figure;
    figure.panels = {errorPanel(report, "Pooled PSNR against full geometry" + suffix, psnr),
                     errorPanel(report, "LDR-FLIP against full geometry" + suffix, flip)};
    figure.width = 1600;
    figure.height = 640;
    figure.legendWidth = 480;
    if (!report.modes.empty() && report.modes[0].mode == Mode::Full)
        figure.note = "#1 " + modeLabel(report.modes[0]) + " is the reference: exact, not drawn";
    return figure;
}

}  // namespace cavewall::bench
