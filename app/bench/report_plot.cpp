#include "app/bench/report_plot.h"

#include <cmath>

namespace cavewall::bench {

namespace {

struct ErrorAxis {
    PlotAxis axis;
    double (*value)(const ModeResult&);  // the plotted figure
    double (*rank)(const ModeResult&);   // lower is better: the Pareto front's error
};

// One panel: every mode with a finite time and figure as its own series, the front over them.
PlotPanel errorPanel(const BenchReport& report, const std::string& title, const ErrorAxis& error) {
    PlotPanel panel;
    panel.title = title;
    panel.x = {"median frame time, all screens", "ms", true};
    panel.y = error.axis;
    panel.controlName = "control: cells without textures";
    panel.alternativeName = "best alternative: full geometry with levels of detail";
    const ModeResult* control = controlMode(report);
    const ModeResult* alternative = lodBaseline(report);
    std::vector<TradeOff> tradeOffs;
    std::vector<std::size_t> seriesOf;
    for (std::size_t i = 0; i < report.modes.size(); ++i) {
        const ModeResult& m = report.modes[i];
        const double x = m.frameMs.p50, y = error.value(m);
        const bool compared = m.error.frames > 0 || i == 0;  // the reference compares with itself
        if (!compared || !std::isfinite(x) || !std::isfinite(y)) continue;
        PlotPoint point{x, y, false, &m == control, &m == alternative};
        panel.series.push_back({"#" + std::to_string(i + 1) + " " + modeLabel(m), {point}, false});
        tradeOffs.push_back({x, error.rank(m)});
    }
    for (std::size_t i : paretoFront(tradeOffs)) panel.series[i].points[0].front = true;
    return panel;
}

}  // namespace

Figure tradeOffFigure(const BenchReport& report) {
    const ErrorAxis psnr{{"pooled PSNR against full geometry", "dB", false},
                         [](const ModeResult& m) { return m.error.psnrDb; },
                         [](const ModeResult& m) { return m.error.rmse; }};
    const ErrorAxis flip{{"LDR-FLIP mean against full geometry (0: identical)", "", true},
                         [](const ModeResult& m) { return m.error.flipMean; },
                         [](const ModeResult& m) { return m.error.flipMean; }};
    const std::string suffix = report.resolution.empty() ? "" : " (" + report.resolution + ")";
    Figure figure;
    figure.panels = {errorPanel(report, "Pooled PSNR against frame time" + suffix, psnr),
                     errorPanel(report, "FLIP against frame time" + suffix, flip)};
    figure.width = 1400;
    figure.height = 640;
    return figure;
}

}  // namespace cavewall::bench
