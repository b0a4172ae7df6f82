#include "display/foldout.h"

#include <gtest/gtest.h>

#include <optional>

namespace cavewall::display {
namespace {

// A preset with every screen at `pixels` x `pixels` (cave4 and cave6 screens are 3 m squares).
std::vector<config::Screen> screensOf(const char* preset, int pixels) {
    auto screens = config::loadDisplayConfig(preset).screens;
    for (auto& s : screens) s.resolution = {pixels, pixels};
    return screens;
}

int indexOf(const std::vector<config::Screen>& screens, const std::string& name) {
    for (int i = 0; i < static_cast<int>(screens.size()); ++i)
        if (screens[i].name == name) return i;
    return -1;
}

struct Probe {
    const char* what;
    glm::ivec2 canvas;
    const char* screen;  // nullptr: background
    glm::ivec2 pixel;
};

void expectProbes(const FoldoutLayout& layout, const std::vector<config::Screen>& screens,
                  std::initializer_list<Probe> probes) {
    for (const Probe& p : probes) {
        SCOPED_TRACE(p.what);
        const std::optional<FoldoutSample> s = layout.sample(p.canvas);
        if (!p.screen) {
            EXPECT_FALSE(s.has_value());
            continue;
        }
        ASSERT_TRUE(s.has_value());
        EXPECT_EQ(s->screen, indexOf(screens, p.screen));
        EXPECT_EQ(s->pixel, p.pixel);
    }
}

TEST(Foldout, Cave4FoldsTheWallsOutAroundTheFloor) {
    const auto screens = screensOf("cave4", 128);
    const FoldoutLayout layout = foldoutLayout(screens);
    // Three 128-pixel tiles across (left, floor, right), two down (front, floor).
    EXPECT_EQ(layout.size, glm::ivec2(384, 256));
    EXPECT_EQ(layout.tiles.front().screen, indexOf(screens, "floor"));  // the floor is the root
    expectProbes(layout, screens,
                 {
                     // The floor's image shows the front edge on top, so it sits below the front wall.
                     {"floor top-left", {128, 128}, "floor", {0, 0}},
                     {"floor bottom-right", {255, 255}, "floor", {127, 127}},
                     // The front's bottom row touches the floor's top row along their shared edge.
                     {"front bottom-left", {128, 127}, "front", {0, 127}},
                     {"front top-right", {255, 0}, "front", {127, 0}},
                     // The left wall's bottom edge runs along the floor's left edge; its front end (image
                     // x = 127) is at the top and going left in the canvas goes up the wall.
                     {"left, front-bottom corner", {127, 128}, "left", {127, 127}},
                     {"left, back-top corner", {0, 255}, "left", {0, 0}},
                     // Mirror image on the right: the front end (image x = 0) at the top.
                     {"right, front-bottom corner", {256, 128}, "right", {0, 127}},
                     {"right, back-top corner", {383, 255}, "right", {127, 0}},
                     {"above the left wall", {10, 10}, nullptr, {}},
                 });
}

TEST(Foldout, Cave6PutsTheBackBelowAndTheCeilingAboveTheFront) {
    const auto screens = screensOf("cave6", 64);
    const FoldoutLayout layout = foldoutLayout(screens);
    // Columns: left, floor, right; rows: ceiling, front, floor, back.
    EXPECT_EQ(layout.size, glm::ivec2(192, 256));
    expectProbes(layout, screens,
                 {
                     {"front bottom-left", {64, 127}, "front", {0, 63}},
                     {"floor top-left", {64, 128}, "floor", {0, 0}},
                     // The back wall hangs below the floor upside down: its bottom edge meets the floor's
                     // bottom (back) edge, and its image x runs right-to-left in the canvas.
                     {"back bottom-left", {127, 192}, "back", {0, 63}},
                     {"back top-right", {64, 255}, "back", {63, 0}},
                     // The ceiling's lower edge is the front wall's top edge.
                     {"ceiling lower-left", {64, 63}, "ceiling", {0, 63}},
                     {"front top-left", {64, 64}, "front", {0, 0}},
                 });
}

TEST(Foldout, PowerWallTilesByPositionOnTheWall) {
    const auto screens = config::loadDisplayConfig("powerwall").screens;
    const FoldoutLayout layout = foldoutLayout(screens, 960.0);  // 1920 px over 2 m
    EXPECT_EQ(layout.size, glm::ivec2(3840, 2160));
    expectProbes(layout, screens,
                 {
                     {"upper-left corner", {0, 0}, "upper-left", {0, 0}},
                     {"lower-right corner", {3839, 2159}, "lower-right", {1919, 1079}},
                     {"upper-right, bottom-left", {1920, 1079}, "upper-right", {0, 1079}},
                 });
}

TEST(Foldout, LooseParallelScreensKeepTheirGap) {
    // Two 1 m screens side by side with a 0.5 m bezel gap share no edge.
    // Headless, any rank, no warp and no blend.
    config::Screen a{"a", {0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {100, 100}, std::nullopt, {}, -1, "", ""};
    config::Screen b{"b", {1.5, 0, 0}, {2.5, 0, 0}, {1.5, 1, 0}, {100, 100}, std::nullopt, {}, -1, "", ""};
    const FoldoutLayout layout = foldoutLayout({a, b});
    EXPECT_EQ(layout.size, glm::ivec2(250, 100));  // 2.5 m at 100 px/m
    expectProbes(layout, {a, b},
                 {
                     {"a", {99, 50}, "a", {99, 50}},
                     {"gap", {125, 50}, nullptr, {}},
                     {"b", {150, 50}, "b", {0, 50}},
                 });
}

TEST(Foldout, CanvasIsClampedToTheLargestTextureSize) {
    auto screens = screensOf("cave4", 16384);
    const FoldoutLayout layout = foldoutLayout(screens);
    // 3 x 16384 px would not fit: the density drops so the widest side is kMaxResolution.
    EXPECT_EQ(layout.size.x, config::kMaxResolution);
    EXPECT_NEAR(layout.pixelsPerMetre, config::kMaxResolution / 9.0, 1e-9);
}

}  // namespace
}  // namespace cavewall::display
