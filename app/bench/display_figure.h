#pragma once
// The picture of a display configuration (`cavewall display CONFIG --png`), drawn by gnuplot
// (app/bench/plot.h): two panels at one scale, in metres, from the front (x across, y up,
// looking down -z as a viewer facing the front wall) and from above (x across, z down the page,
// looking down -y). Each screen is its outline, lightly filled, in a colour of its own and named
// at its centre (a screen seen edge-on: at the tip of its normal); its normal is an arrow from
// the centre towards the front side, where the viewer belongs (none where it points out of or
// into the page). The default head is a marker with an arrow along its view direction, both
// eyes are markers when the display is stereo, and the tracking volume is a box when the
// configuration sets one. Edges two screens share lie on a wide grey band, and the area two
// screens in one plane both cover is filled red (display/display_summary.h).

#include "app/bench/plot.h"
#include "config/display_config.h"

#include <string>

namespace cavewall::bench {

struct DisplayFigureOptions {
    std::string title;      // leads both panels' titles; empty: the configuration's name
    int width = 1400;       // PNG pixels
    int height = 640;       // PNG pixels
    int legendWidth = 360;  // the shared legend's strip at the right, pixels
};

// Names of the series besides the screens' own, for callers and tests that look them up.
inline constexpr const char* kSharedEdgeSeries = "edge shared by two screens";
inline constexpr const char* kOverlapSeries = "screens covering the same area";
inline constexpr const char* kNormalSeries = "normal (to the front side)";
inline constexpr const char* kHeadSeries = "default head";
inline constexpr const char* kViewSeries = "default view direction";
inline constexpr const char* kTrackingSeries = "tracking volume";

// The figure of `config` (validated). Panel 0: from the front; panel 1: from above. Each screen
// has one series named after it (its outline) and one unnamed (its fill); both panels list the
// same series in the same order (one shared legend, the second panel's).
Figure displayFigure(const config::DisplayConfig& config, const DisplayFigureOptions& options = {});

}  // namespace cavewall::bench
