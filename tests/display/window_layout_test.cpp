// Windows of a CAVE's screens on a desktop or an image generator (display/window_layout.h):
// tiled windows never overlap and stay on their monitor, scaled down only when needed;
// configured positions and fullscreen windows keep to their monitor.
#include "display/window_layout.h"

#include "config/error.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace cavewall::display {
namespace {

using ::testing::HasSubstr;

// Each window's frame: its content plus the title bar above it (`aTitle`, `bTitle` pixels).
bool overlap(const WindowPlacement& a, const WindowPlacement& b, int aTitle, int bTitle) {
    const glm::ivec2 a0 = a.position - glm::ivec2(0, aTitle), a1 = a.position + a.size;
    const glm::ivec2 b0 = b.position - glm::ivec2(0, bTitle), b1 = b.position + b.size;
    return a0.x < b1.x && b0.x < a1.x && a0.y < b1.y && b0.y < a1.y;
}

bool inside(const WindowPlacement& w, const MonitorArea& m, int titleBar) {
    return w.position.x >= m.position.x && w.position.y - titleBar >= m.position.y &&
           w.position.x + w.size.x <= m.position.x + m.size.x && w.position.y + w.size.y <= m.position.y + m.size.y;
}

std::vector<WindowWish> squares(int count, int side) {
    std::vector<WindowWish> wishes;
    for (int i = 0; i < count; ++i)
        wishes.push_back({.name = "s" + std::to_string(i), .size = {side, side}, .position = std::nullopt});
    return wishes;
}

TEST(WindowLayout, FourCaveScreensOnAFullHdMonitorTileTwoByTwoWithoutOverlap) {
    const MonitorArea monitor{{0, 0}, {1920, 1080}};
    const std::vector<WindowPlacement> p = layoutWindows(squares(4, 1024), {monitor});
    ASSERT_EQ(p.size(), 4u);
    // 2 x 2 cells of 960 x 540 with a 32-pixel title bar: 508 / 1024 of the wished side.
    for (const WindowPlacement& w : p) {
        EXPECT_EQ(w.size, glm::ivec2(508));
        EXPECT_TRUE(inside(w, monitor, kTitleBarPixels));
    }
    for (std::size_t i = 0; i < p.size(); ++i)
        for (std::size_t j = i + 1; j < p.size(); ++j)
            EXPECT_FALSE(overlap(p[i], p[j], kTitleBarPixels, kTitleBarPixels)) << i << j;
    EXPECT_EQ(p[1].position, glm::ivec2(960, 32));  // second column, first row
}

TEST(WindowLayout, WindowsThatFitKeepTheirSize) {
    const std::vector<WindowPlacement> p = layoutWindows(squares(2, 300), {{{0, 0}, {1280, 1024}}});
    EXPECT_EQ(p[0].size, glm::ivec2(300));
    EXPECT_EQ(p[1].size, glm::ivec2(300));
    EXPECT_EQ(p[0].scale, 1.0);
    EXPECT_FALSE(overlap(p[0], p[1], kTitleBarPixels, kTitleBarPixels));
}

TEST(WindowLayout, ManyWindowsOfEveryShapeNeverOverlapAndStayOnScreen) {
    const std::vector<MonitorArea> monitors{{{0, 0}, {1000, 700}}, {{1000, 24}, {800, 576}}};
    for (int count = 1; count <= 9; ++count) {
        std::vector<WindowWish> wishes;
        for (int i = 0; i < count; ++i)
            wishes.push_back({.name = "s",
                              .size = {400 + 173 * i, 900 - 61 * i},
                              .position = std::nullopt,
                              .monitor = i % 2,
                              .borderless = i % 3 == 0});
        const std::vector<WindowPlacement> p = layoutWindows(wishes, monitors);
        for (int i = 0; i < count; ++i) {
            SCOPED_TRACE("count " + std::to_string(count) + ", window " + std::to_string(i));
            const auto title = [&](int k) { return wishes[k].borderless ? 0 : kTitleBarPixels; };
            EXPECT_TRUE(inside(p[i], monitors[i % 2], title(i)));
            EXPECT_LE(p[i].size.x, wishes[i].size.x);
            for (int j = i + 1; j < count; ++j) EXPECT_FALSE(overlap(p[i], p[j], title(i), title(j))) << j;
        }
    }
}

TEST(WindowLayout, ConfiguredPositionsAreOnTheirMonitor) {
    const std::vector<MonitorArea> monitors{{{0, 0}, {1920, 1080}}, {{1920, 0}, {1024, 768}}};
    std::vector<WindowWish> wishes = squares(1, 500);
    wishes[0].monitor = 1;
    wishes[0].position = glm::ivec2(10, 20);
    EXPECT_EQ(layoutWindows(wishes, monitors)[0].position, glm::ivec2(1930, 20));
    wishes[0].fullscreen = true;
    const WindowPlacement full = layoutWindows(wishes, monitors)[0];
    EXPECT_EQ(full.position, glm::ivec2(1920, 0));
    EXPECT_EQ(full.size, glm::ivec2(1024, 768));
}

TEST(WindowLayout, AMonitorThatIsNotConnectedIsAnErrorNamingTheScreen) {
    std::vector<WindowWish> wishes = squares(1, 500);
    wishes[0].name = "left";
    wishes[0].monitor = 3;
    EXPECT_THAT(
        [&] {
            layoutWindows(wishes, {{{0, 0}, {1920, 1080}}});
        },
        ::testing::ThrowsMessage<Error>(
            HasSubstr("screen 'left': window.monitor: expected a monitor index in [0, 0] (1 monitor), got 3")));
}

// A window of another shape than its image (resized by the user) shows the image whole and
// undistorted, centred between black bars.
TEST(FitImage, KeepsTheImagesAspectCentredInAnyWindow) {
    // The desktop's 1920 x 1080 image in its 1280 x 720 window: the whole window.
    EXPECT_EQ(fitImage({1920, 1080}, {1280, 720}), glm::ivec4(0, 0, 1280, 720));
    // A portrait window: bars above and below, 600 x 337.5 -> 338 rows centred in 800.
    EXPECT_EQ(fitImage({1920, 1080}, {600, 800}), glm::ivec4(0, 231, 600, 569));
    // A wide window: bars left and right, 400 x 300 centred in 1000.
    EXPECT_EQ(fitImage({1024, 768}, {1000, 300}), glm::ivec4(300, 0, 700, 300));
    // Aspects a pixel apart (an odd window size) fill the window: no one-pixel bar.
    EXPECT_EQ(fitImage({1920, 1080}, {1281, 720}), glm::ivec4(0, 0, 1281, 720));
    // Every rectangle keeps the image's aspect to within a pixel and lies in the window.
    for (const glm::ivec2 window : {glm::ivec2(1, 1), glm::ivec2(3, 1000), glm::ivec2(1000, 3), glm::ivec2(777, 555)}) {
        const glm::ivec4 r = fitImage({1920, 1080}, window);
        SCOPED_TRACE(testing::Message() << window.x << " x " << window.y);
        EXPECT_GE(r.x, 0);
        EXPECT_GE(r.y, 0);
        EXPECT_LE(r.z, window.x);
        EXPECT_LE(r.w, window.y);
        EXPECT_GE(r.z - r.x, 1);
        EXPECT_GE(r.w - r.y, 1);
        EXPECT_NEAR(double(r.z - r.x) * 1080.0, double(r.w - r.y) * 1920.0, 1920.0);
    }
    // A minimised window or an empty image: nothing to draw.
    EXPECT_EQ(fitImage({1920, 1080}, {0, 0}), glm::ivec4(0));
    EXPECT_EQ(fitImage({0, 1080}, {640, 480}), glm::ivec4(0));
}

}  // namespace
}  // namespace cavewall::display
