#pragma once
// The demo's trade-off: its four runs as a bench report (app/bench/report.h), so that the
// bench's rule (app/bench/recommend.h) and plot (app/bench/report_plot.h) apply to them, and
// the machine's load around the runs.

#include "app/bench/report.h"

#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::bench {

// One run of the demo: what it drew, its median frame time and its image error against full
// geometry at full detail (the reference; its error is left at the defaults).
struct DemoMode {
    Mode mode = Mode::Full;
    double lodPixels = 0.0;
    walls::WallKind wallKind = walls::WallKind::Flat;  // the walls run's
    double alphaDeg = 0.0;                             // the walls run's
    double medianMs = 0.0;
    ImageError error{};
    bool control = false;  // the control (cells without textures), ringed in the plot as the bench's
};

// The runs as a report, the reference first (`modes[0]` must be full geometry at full
// detail), with `resolution` ("32x32 per screen, mono") and the recommendation filled in.
BenchReport demoReport(const std::vector<DemoMode>& modes, const std::string& resolution);

// Writes `folder`/bench.png (the bench's plot of `report`) when gnuplot is installed; returns
// the report.md lines: the recommendation and the plot, or why there is none.
std::vector<std::string> writeDemoFront(const std::filesystem::path& folder, const BenchReport& report);

// The first three fields of /proc/loadavg ("7.39 9.99 12.25": 1, 5 and 15 minutes), or
// "unknown" where it cannot be read.
std::string loadAverage();

}  // namespace cavewall::bench
