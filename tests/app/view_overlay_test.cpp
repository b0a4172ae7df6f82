// The status line, help page and window title of a windowed session (app/view_overlay.h).
#include "app/view_overlay.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::app {
namespace {

using ::testing::Contains;
using ::testing::HasSubstr;

TEST(ViewOverlay, OneStatusLineNamesTheModeSpeedFrameTimeAndTheHelpKey) {
    const display::OverlayText o = viewOverlay({.navigation = "walk", .speed = 2.5, .frameMs = 16.66});
    ASSERT_EQ(o.lines.size(), 1u);
    EXPECT_EQ(o.lines[0], "walk | 2.50 m/s | 16.7 ms | F1: help");
    // A tracker has no desktop speed.
    EXPECT_EQ(viewOverlay({.navigation = "guided", .frameMs = 40.0}).lines[0], "guided | 40.0 ms | F1: help");
}

TEST(ViewOverlay, TheHelpPageListsTheKeysAboveTheStatusLine) {
    const display::OverlayText o = viewOverlay({.navigation = "fly", .speed = 1.0, .help = true});
    EXPECT_EQ(o.lines, [] {
        std::vector<std::string> lines = helpLines(0.15);
        lines.push_back("fly | 1.00 m/s | 0.0 ms | F1: help");
        return lines;
    }());
    EXPECT_THAT(o.lines, Contains(HasSubstr("0.15 deg per pixel")));
    for (const char* key : {"W A S D", "Q E", "Shift", "wheel", "1 2 3 4", "F1 or H", "Esc", "Ctrl+Q"})
        EXPECT_THAT(o.lines, Contains(HasSubstr(key))) << key;
}

TEST(ViewOverlay, WhatIsDrawnBakingAndTheTrackerAreShown) {
    // What the walls draw goes on the status line.
    EXPECT_EQ(viewOverlay({.navigation = "fly", .frameMs = 20.0, .drawing = "walls"}).lines,
              std::vector<std::string>{"fly | 20.0 ms | walls | F1: help"});
    // Baking on demand and a network tracker get a second line.
    const display::OverlayText o = viewOverlay({.navigation = "none",
                                                .frameMs = 20.0,
                                                .drawing = "walls",
                                                .texturesToBake = 300,
                                                .texturesBaked = 40,
                                                .tracker = "no data"});
    ASSERT_EQ(o.lines.size(), 2u);
    EXPECT_EQ(o.lines[1], "baking walls 40/340, geometry meanwhile | tracker: no data");
    // Once everything is baked the second line goes.
    EXPECT_EQ(viewOverlay({.navigation = "fly", .drawing = "walls", .texturesBaked = 340}).lines.size(), 1u);
}

TEST(ViewOverlay, TheTitleNamesTheScreenAndTheNavigation) {
    EXPECT_EQ(windowTitle("monitor", "fly"), "cavewall - monitor - fly");
}

}  // namespace
}  // namespace cavewall::app
