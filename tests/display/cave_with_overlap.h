#pragma once
// A display with an overlap, for the tests of what `cavewall display` reports and draws
// (tests/display/display_summary_test.cpp, tests/app/bench/display_figure_test.cpp).

#include "config/display_config.h"

namespace cavewall::test {

// cave4, mono, with a 1.5 x 1 m screen "extra" in the front wall's plane, its left 0.5 m over the
// front wall from 1 to 2 m up: the two cover 0.5 x 1 = 0.5 m² twice.
inline config::DisplayConfig caveWithOverlap() {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    config::Screen extra = c.screens[0];
    extra.name = "extra";
    extra.lowerLeft = {1.0, 1.0, -1.5};
    extra.lowerRight = {2.5, 1.0, -1.5};
    extra.upperLeft = {1.0, 2.0, -1.5};
    c.screens.push_back(extra);
    c.stereo = config::StereoMode::Mono;  // the preset is stereo
    return c;
}

}  // namespace cavewall::test
