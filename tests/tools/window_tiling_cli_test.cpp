// The four windows of cave4 on one 1920 x 1080 monitor (a virtual X server, ctest runs this
// executable through `xvfb-run`): tiled without overlapping, all on screen, each smaller than
// its screen's 1024 x 1024 pixels, while the rendered images keep that resolution
// (display/window_layout.h). No fixed sleeps: each step polls for what it waits for.
#include "tests/tools/run_cli_support.h"
#include "tests/support/csv_table.h"

#include "scenes/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <csignal>
#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>
#include <thread>

namespace cavewall::test {
namespace {

namespace fs = std::filesystem;

const std::string kRoom = std::string(CAVEWALL_REAL_SCENES) + "/OcclusionRoom/room.glb";

struct Rect {
    int x = 0, y = 0, w = 0, h = 0;
};

bool overlap(const Rect& a, const Rect& b) {
    return a.x < b.x + b.w && b.x < a.x + a.w && a.y < b.y + b.h && b.y < a.y + a.h;
}

// The windows whose title starts with "cavewall - " (set at the first frame), by xdotool.
std::vector<Rect> sessionWindows() {
    std::vector<Rect> out;
    std::istringstream ids(shell("xdotool search --name '^cavewall - ' 2>/dev/null"));
    for (std::string id; std::getline(ids, id);) {
        const std::string g = shell("xdotool getwindowgeometry " + id);
        std::smatch m;
        if (!std::regex_search(g, m, std::regex("Position: (-?[0-9]+),(-?[0-9]+).*\\n.*Geometry: ([0-9]+)x([0-9]+)")))
            continue;
        out.push_back({std::stoi(m[1]), std::stoi(m[2]), std::stoi(m[3]), std::stoi(m[4])});
    }
    return out;
}

TEST(WindowTiling, Cave4OnAFullHdMonitorGetsFourWindowsSideBySideAtItsOwnResolution) {
    const char* display = std::getenv("DISPLAY");
    ASSERT_TRUE(display && *display) << "no $DISPLAY (ctest runs this under xvfb-run)";
    const fs::path out = outputDir("window-tiling");
    CliProcess view({"view", kRoom, "--display", "cave4", "--mono", "--out", out.string(), "--save-frames", "every:2"});
    std::vector<Rect> windows;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(2);
    while ((windows = sessionWindows()).size() < 4) {
        ASSERT_FALSE(view.exited()) << view.finish(std::chrono::seconds(5)).err;
        ASSERT_LT(std::chrono::steady_clock::now(), deadline) << windows.size() << " windows";
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a polling interval
    }
    // Frame 2 saved: its images are written once frame 3 has a row in frames.csv.
    for (;;) {
        std::ifstream in(out / "frames.csv");
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        if (!text.empty() && parseCsv(text, "frames.csv").size() >= 4) break;
        ASSERT_FALSE(view.exited()) << view.finish(std::chrono::seconds(5)).err;
        ASSERT_LT(std::chrono::steady_clock::now(), deadline);
        std::this_thread::sleep_for(std::chrono::milliseconds(50));  // a polling interval
    }
    view.signal(SIGINT);
    const CliResult r = view.finish(std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 128 + SIGINT) << r.err;

    ASSERT_EQ(windows.size(), 4u);
    for (std::size_t i = 0; i < windows.size(); ++i) {
        const Rect& w = windows[i];
        SCOPED_TRACE("window at " + std::to_string(w.x) + "," + std::to_string(w.y) + " " + std::to_string(w.w) + "x" +
                     std::to_string(w.h));
        EXPECT_GE(w.x, 0);
        EXPECT_GE(w.y, 0);
        EXPECT_LE(w.x + w.w, 1920);
        EXPECT_LE(w.y + w.h, 1080);
        EXPECT_LT(w.w, 1024);  // scaled down to fit
        EXPECT_EQ(w.w, w.h);   // keeping the screens' square aspect
        for (std::size_t j = i + 1; j < windows.size(); ++j) EXPECT_FALSE(overlap(w, windows[j])) << j;
    }
    for (const char* screen : {"front", "left", "right", "floor"}) {
        const scenes::Image image = scenes::readImage(out / "frames" / "00002" / (std::string(screen) + ".png"));
        EXPECT_EQ(image.width, 1024) << screen;
        EXPECT_EQ(image.height, 1024) << screen;
    }
}

}  // namespace
}  // namespace cavewall::test
