#include "app/bench/demo_front.h"

#include "app/bench/gnuplot.h"
#include "app/bench/report_plot.h"

#include <cstdlib>
#include <fstream>

namespace cavewall::bench {

BenchReport demoReport(const std::vector<DemoMode>& modes, const std::string& resolution) {
    BenchReport report;
    report.resolution = resolution;
    for (const DemoMode& d : modes) {
        ModeResult m;
        m.mode = d.mode;
        m.lodPixels = d.lodPixels;
        if (d.mode == Mode::Walls) {
            m.wallKind = d.wallKind;
            m.alphaDeg = d.alphaDeg;
            m.transition = app::Transition::Blend;
        }
        m.frameMs.p50 = d.medianMs;
        m.error = d.error;
        if (d.control) report.control = report.modes.size();
        report.modes.push_back(m);
    }
    compareWithControl(report);
    compareWithLodBaseline(report);
    recommend(report);
    return report;
}

std::vector<std::string> writeDemoFront(const std::filesystem::path& folder, const BenchReport& report) {
    std::vector<std::string> lines = {recommendedLine(report) +
                                      "; the bench's rule (docs/benchmarking.md) "
                                      "over this demo's four runs"};
    const char* path = std::getenv("PATH");
    if (findProgram("gnuplot", path ? path : "/usr/local/bin:/usr/bin:/bin").empty()) {
        lines.push_back("No plot of the front: gnuplot is not installed (gnuplot-nox).");
        return lines;
    }
    writePlot(folder / "bench.png", tradeOffFigure(report));
    lines.push_back(
        "![pooled PSNR and FLIP mean against median frame time of the four runs; dashed: the Pareto "
        "front; circle: the control; square: the best alternative; diamond: the recommended walls mode](bench.png)");
    return lines;
}

std::string loadAverage() {
    std::ifstream in("/proc/loadavg");
    std::string one, five, fifteen;
    if (!(in >> one >> five >> fifteen)) return "unknown";
    return one + " " + five + " " + fifteen;
}

}  // namespace cavewall::bench
