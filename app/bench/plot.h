#pragma once
// A small CPU-rasterised scatter plot for `cavewall bench`: error (RMSE, y) against frame time
// (median ms, x), one numbered point per mode, the Pareto front (app/bench/metrics.h)
// marked in red and joined by a line, axes with a few tick labels drawn in a built-in 3x5
// digit font. No text beyond digits: point numbers match the "#" column of bench.md.

#include "scenes/scene.h"

#include <string>
#include <vector>

namespace cavewall::bench {

struct PlotPoint {
    double x = 0.0, y = 0.0;  // finite; frame ms and RMSE
    int label = 0;            // drawn next to the point
    bool front = false;       // on the Pareto front
};

// An opaque RGBA image of `width` x `height` pixels (at least 160 x 120).
scenes::Image plotTradeOff(const std::vector<PlotPoint>& points, int width = 640, int height = 420);

// One line of plotSeries: its points joined in x order, drawn in colour `label` % 4 (blue,
// red, green, orange) with `label` beside its last point.
struct PlotSeries {
    std::vector<PlotPoint> points;  // x, y finite and >= 0; label and front unused
    int label = 0;
};

// A line chart of `series` from the origin, axes with tick labels (`cavewall bench --scale`:
// frame time, memory or load time against triangles).
scenes::Image plotSeries(const std::vector<PlotSeries>& series, int width = 640, int height = 420);

// Draws `text` (digits, '.', '-', 'e', '+'; other characters are blank) with its top-left at
// (x, y), each glyph 3x5 cells of `scale` pixels. Exposed for tests.
void drawText(scenes::Image& image, int x, int y, const std::string& text, int scale, const unsigned char rgb[3]);

}  // namespace cavewall::bench
