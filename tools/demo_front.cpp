#include "tools/demo_front.h"

#include "app/bench/gnuplot.h"
#include "app/bench/report_plot.h"

#include <cstdlib>
#include <fstream>

namespace cavewall::tools {

bench::BenchReport demoReport(const std::vector<DemoMode>& modes, const std::string& resolution) {
    bench::BenchReport report;
    report.resolution = resolution;
    for (const DemoMode& d : modes) {
        bench::ModeResult m;
        m.mode = d.mode;
        m.lodPixels = d.lodPixels;
        if (d.mode == bench::Mode::Walls) {
            m.wallKind = d.wallKind;
            m.alphaDeg = d.alphaDeg;
            m.transition = app::Transition::Blend;
        }
        m.frameMs.p50 = d.medianMs;
        m.error = d.error;
        if (d.control) report.control = report.modes.size();
        report.modes.push_back(m);
    }
    bench::compareWithControl(report);
    bench::compareWithLodBaseline(report);
    bench::recommend(report);
    return report;
}

std::vector<std::string> writeDemoFront(const std::filesystem::path& folder, const bench::BenchReport& report) {
    std::vector<std::string> lines = {bench::recommendedLine(report) +
                                      "; the bench's rule (docs/benchmarking.md) "
                                      "over this demo's four runs"};
    const char* path = std::getenv("PATH");
    if (bench::findProgram("gnuplot", path ? path : "/usr/local/bin:/usr/bin:/bin").empty()) {
        lines.push_back("No plot of the front: gnuplot is not installed (gnuplot-nox).");
        return lines;
    }
    bench::writePlot(folder / "bench.png", bench::tradeOffFigure(report));
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

}  // namespace cavewall::tools
