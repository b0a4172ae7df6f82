// `cavewall view` in a real window under a virtual X server, driven through it by xdotool: the
// first image shows the model, W moves the viewer along the view, a drag turns the view by the
// stated degrees per pixel, F1 shows the help over the window and never in the saved frames,
// Escape frees the pointer and a second Escape quits with exit 0 and complete files; a window
// resized to another shape shows the image undistorted between black bars, or, when it
// reframes, more or less of the scene without bars.
// ctest runs this executable through `xvfb-run`. There are no fixed sleeps: each step polls
// frames.csv (flushed after every frame) for the frame or the pose it waits for.
#include "tests/tools/run_cli_support.h"
#include "tests/support/csv_table.h"

#include "scenes/image_io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <thread>

namespace cavewall::test {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

const std::string kRoom = std::string(CAVEWALL_REAL_SCENES) + "/OcclusionRoom/room.glb";
constexpr int kSaveEvery = 5;              // frames between saved frames
constexpr double kDegreesPerPixel = 0.15;  // view --help's mouse look

// A desktop monitor drawn at 160 x 90 in a 640 x 360 window (the help page fits at scale 2);
// `resize`: the window's "resize" ("letterbox", the default, or "reframe").
fs::path smallDesktop(const fs::path& folder, const std::string& resize = "letterbox") {
    const fs::path file = folder / ("small_desktop_" + resize + ".json");
    std::ofstream(file) << R"({"name": "small", "screens": [{"name": "monitor",
        "lowerLeft": [-0.3, 1.03, -0.6], "lowerRight": [0.3, 1.03, -0.6], "upperLeft": [-0.3, 1.37, -0.6],
        "resolution": [160, 90], "output": {"window": {"position": [0, 0], "size": [640, 360], "resize": ")"
                        << resize << R"("}}}], "viewer": {"headPosition": [0, 1.2, 0]}})";
    return file;
}

class ViewWindow : public ::testing::Test {
protected:
    void SetUp() override {
        const char* display = std::getenv("DISPLAY");
        if (!display || !*display) GTEST_SKIP() << "no $DISPLAY (ctest runs this under xvfb-run)";
        _out = outputDir("view-window");
    }

    // The window of the running view, focused for xdotool's keys.
    void openWindow(CliProcess& view) {
        _window = shell("timeout 60 xdotool search --sync --name 'monitor' | head -n 1");
        _window.erase(_window.find_last_not_of("\n") + 1);
        ASSERT_FALSE(_window.empty()) << view.finish(std::chrono::seconds(5)).err;
        // The window may not accept focus until it is mapped: try until it does or view ends.
        while (std::system(("xdotool windowfocus --sync " + _window + " 2>/dev/null").c_str()) != 0)
            ASSERT_FALSE(view.exited()) << view.finish(std::chrono::seconds(5)).err;
    }

    void xdotool(const std::string& args) { ASSERT_EQ(std::system(("xdotool " + args).c_str()), 0) << args; }

    // The rows of frames.csv so far; parseCsv refuses a partial row, and rows are flushed whole.
    CsvTable rows() const {
        std::ifstream in(_out / "frames.csv");
        const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        return text.empty() ? CsvTable{} : parseCsv(text, "frames.csv");
    }

    // Polls frames.csv until `done` holds for its rows; fails after a minute or when view ends.
    CsvTable waitFor(CliProcess& view, const std::string& what, const std::function<bool(const CsvTable&)>& done) {
        const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(1);
        for (;;) {
            CsvTable t = rows();
            if (!t.empty() && done(t)) return t;
            if (view.exited() || std::chrono::steady_clock::now() > deadline) {
                ADD_FAILURE() << "gave up waiting for " << what << "; " << t.size() << " frames";
                return t;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(20));  // a polling interval
        }
    }

    // Waits until `count` more frames have been drawn after the last row of `t`.
    CsvTable waitFrames(CliProcess& view, const CsvTable& t, std::size_t count) {
        const std::size_t target = t.size() + count;
        return waitFor(view, std::to_string(target) + " frames", [&](const CsvTable& r) { return r.size() >= target; });
    }

    // A saved frame's image: the scene ("monitor") or the window ("window-monitor").
    scenes::Image image(long frame, const std::string& stem) const {
        char name[16];
        std::snprintf(name, sizeof name, "%05ld", frame);
        return scenes::readImage(_out / "frames" / name / (stem + ".png"));
    }

    // The last frame saved at or before the last row of `t` whose files are all written (the
    // next frame has begun).
    static long lastSaved(const CsvTable& t) {
        const long last = std::stol(t.back().at("frame"));
        return (last - 1) / kSaveEvery * kSaveEvery;
    }

    fs::path _out;
    std::string _window;
};

glm::dvec3 world(const CsvRow& row) { return {row.number("world_x"), row.number("world_y"), row.number("world_z")}; }

std::size_t distinctColours(const scenes::Image& image) {
    std::set<std::uint32_t> colours;
    for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4)
        colours.insert(image.rgba[i] | image.rgba[i + 1] << 8 | image.rgba[i + 2] << 16);
    return colours.size();
}

// The share of pixels in the rectangle [x0, x1) x [y0, y1) whose channels differ by more than
// 24 levels between two images of one size.
double changedShare(const scenes::Image& a, const scenes::Image& b, int x0, int y0, int x1, int y1) {
    int changed = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const std::size_t i = 4 * (static_cast<std::size_t>(y) * a.width + x);
            for (int c = 0; c < 3; ++c)
                if (std::abs(a.rgba[i + c] - b.rgba[i + c]) > 24) {
                    ++changed;
                    break;
                }
        }
    return static_cast<double>(changed) / ((x1 - x0) * (y1 - y0));
}

TEST_F(ViewWindow, KeysAndMouseMoveTheViewF1ShowsHelpAndEscapeTwiceQuits) {
    CliProcess view({"view", kRoom, "--display", smallDesktop(_out).string(), "--out", _out.string(), "--save-frames",
                     "every:" + std::to_string(kSaveEvery), "--save-window"});
    ASSERT_NO_FATAL_FAILURE(openWindow(view));
    CsvTable t = waitFor(view, "the first frames", [](const CsvTable& r) { return r.size() > kSaveEvery + 1; });
    ASSERT_GT(t.size(), static_cast<std::size_t>(kSaveEvery + 1));
    // The first image shows the model: not one colour.
    EXPECT_GT(distinctColours(image(0, "monitor")), 3u);

    // W held: the viewer moves along the view (yaw 0 looks down -Z; positive yaw turns left).
    const glm::dvec3 before = world(t.back());
    const double yaw = glm::radians(t.back().number("view_yaw_deg"));
    const long savedBefore = lastSaved(t);
    xdotool("keydown w");
    t = waitFor(view, "a step forward",
                [&](const CsvTable& r) { return glm::distance(world(r.back()), before) > 0.2; });
    xdotool("keyup w");
    const glm::dvec3 moved = world(t.back()) - before;
    EXPECT_NEAR(glm::distance(glm::normalize(moved), glm::dvec3(-std::sin(yaw), 0.0, -std::cos(yaw))), 0.0, 1e-6);
    t = waitFrames(view, t, 2 * kSaveEvery);  // a frame saved after the step
    EXPECT_GT(changedShare(image(savedBefore, "monitor"), image(lastSaved(t), "monitor"), 0, 0, 160, 90), 0.01);

    // A drag 100 px to the right: the first press captures the pointer (the window centres
    // it), then the motion turns the view 100 x 0.15 = 15 degrees to the right.
    const double yawBefore = t.back().number("view_yaw_deg");
    xdotool("mousemove --window " + _window + " 320 180 mousedown 1");
    t = waitFrames(view, t, 3);  // the window has taken the press and captured the pointer
    xdotool("mousemove_relative -- 100 0 mouseup 1");
    const double turned = yawBefore - 100.0 * kDegreesPerPixel;
    t = waitFor(view, "the turn",
                [&](const CsvTable& r) { return std::abs(r.back().number("view_yaw_deg") - yawBefore) > 1.0; });
    t = waitFrames(view, t, 3);  // and no more motion arrives
    EXPECT_NEAR(t.back().number("view_yaw_deg"), turned, 1e-3);

    // F1: the help page over the window. The help box (9 lines of 24 px under the status line)
    // darkens the window's upper left; the saved frames are polled until one shows it.
    t = waitFrames(view, t, kSaveEvery + 1);
    const long plain = lastSaved(t);
    const scenes::Image windowPlain = image(plain, "window-monitor");
    xdotool("key F1");
    long help = plain;
    t = waitFor(view, "the help page in the window", [&](const CsvTable& r) {
        if (lastSaved(r) == help) return false;
        help = lastSaved(r);
        return changedShare(windowPlain, image(help, "window-monitor"), 16, 40, 300, 200) > 0.5;
    });
    EXPECT_GT(changedShare(windowPlain, image(help, "window-monitor"), 16, 40, 300, 200), 0.5);
    // The saved scene image is unchanged: the overlay is only in the window (nothing moves).
    EXPECT_EQ(image(plain, "monitor").rgba, image(help, "monitor").rgba) << "frames " << plain << " and " << help;

    // Escape frees the captured pointer; view goes on. A second Escape quits.
    xdotool("key Escape");
    t = waitFrames(view, t, 5);
    EXPECT_FALSE(view.exited());
    xdotool("key Escape");
    const CliResult r = view.finish(std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 0) << r.err;
    std::smatch m;
    ASSERT_TRUE(std::regex_search(r.out, m, std::regex("view: stopped after ([0-9]+) frames: quit"))) << r.out;
    EXPECT_EQ(rows().size(), std::stoul(m[1]));  // every frame's row, complete
}

// Whether every pixel of image row `y` (top first) is black.
bool blackRow(const scenes::Image& image, int y) {
    for (int x = 0; x < image.width; ++x) {
        const std::size_t i = 4 * (static_cast<std::size_t>(y) * image.width + x);
        if (image.rgba[i] != 0 || image.rgba[i + 1] != 0 || image.rgba[i + 2] != 0) return false;
    }
    return true;
}

// A window resized to another shape shows the image whole and undistorted: the 16:9 image in a
// square window of 360 x 360 is 360 x 203 pixels, centred between black bars (the status line
// lies over the upper bar).
TEST_F(ViewWindow, AWindowResizedToAnotherShapeShowsTheImageWholeBetweenBlackBars) {
    CliProcess view({"view", kRoom, "--display", smallDesktop(_out).string(), "--out", _out.string(), "--save-frames",
                     "every:" + std::to_string(kSaveEvery), "--save-window"});
    ASSERT_NO_FATAL_FAILURE(openWindow(view));
    CsvTable t = waitFor(view, "the first frames", [](const CsvTable& r) { return r.size() > kSaveEvery + 1; });
    EXPECT_EQ(image(lastSaved(t), "window-monitor").width, 640);
    EXPECT_FALSE(blackRow(image(lastSaved(t), "window-monitor"), 359));  // no bar at the window's shape
    xdotool("windowsize " + _window + " 360 360");
    t = waitFor(view, "a saved frame of the resized window",
                [&](const CsvTable& r) { return image(lastSaved(r), "window-monitor").width == 360; });
    const scenes::Image shown = image(lastSaved(t), "window-monitor");
    ASSERT_EQ(shown.height, 360);
    // Rows 0-78 and 282-359 are the bars (203 image rows from row 79); one row of rounding.
    for (int y = 283; y < 360; ++y) EXPECT_TRUE(blackRow(shown, y)) << "row " << y;
    for (int y = 80; y < 281; y += 20) EXPECT_FALSE(blackRow(shown, y)) << "row " << y;
    EXPECT_FALSE(blackRow(shown, 180));
    xdotool("key Escape");
    const CliResult r = view.finish(std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

// A window that reframes takes its screen to the window's shape: the square window shows no
// bars, and the scene image (still 160 x 90 pixels) holds a narrower view than before while the
// viewer stands still: the same scene squeezed across, which the window stretches back.
TEST_F(ViewWindow, AWindowThatReframesShowsMoreOrLessOfTheSceneWithoutBars) {
    CliProcess view({"view", kRoom, "--display", smallDesktop(_out, "reframe").string(), "--out", _out.string(),
                     "--save-frames", "every:" + std::to_string(kSaveEvery), "--save-window"});
    ASSERT_NO_FATAL_FAILURE(openWindow(view));
    CsvTable t = waitFor(view, "two saved frames", [](const CsvTable& r) { return r.size() > 2 * kSaveEvery + 1; });
    EXPECT_EQ(t.back().number("lod_px"), 1.0);  // view draws levels of detail within a pixel
    const scenes::Image before = image(lastSaved(t), "monitor");
    ASSERT_EQ(before.rgba, image(lastSaved(t) - kSaveEvery, "monitor").rgba);  // the viewer stands still
    xdotool("windowsize " + _window + " 360 360");
    t = waitFor(view, "a saved frame of the resized window",
                [&](const CsvTable& r) { return image(lastSaved(r), "window-monitor").width == 360; });
    const scenes::Image shown = image(lastSaved(t), "window-monitor");
    ASSERT_EQ(shown.height, 360);
    for (int y = 0; y < 360; y += 20) EXPECT_FALSE(blackRow(shown, y)) << "row " << y;
    EXPECT_FALSE(blackRow(shown, 359));
    const scenes::Image after = image(lastSaved(t), "monitor");
    ASSERT_EQ(after.width, 160);
    // Square, the screen is 0.34 m wide instead of 0.34 * 16 / 9: column x shows what column
    // 79.5 + (x - 79.5) * 9 / 16 showed (rows unchanged). Compare the mapped columns, and the
    // unmapped ones as the control: the mapped must match far better.
    auto share = [&](bool mapped) {
        int changed = 0, total = 0;
        for (int x = 8; x < 152; x += 8) {
            const int from = mapped ? static_cast<int>(std::lround(79.5 + (x - 79.5) * 9.0 / 16.0)) : x;
            for (int y = 0; y < 90; ++y, ++total) {
                const std::size_t a = 4 * (static_cast<std::size_t>(y) * 160 + x);
                const std::size_t b = 4 * (static_cast<std::size_t>(y) * 160 + from);
                for (int c = 0; c < 3; ++c)
                    if (std::abs(after.rgba[a + c] - before.rgba[b + c]) > 24) {
                        ++changed;
                        break;
                    }
            }
        }
        return static_cast<double>(changed) / total;
    };
    EXPECT_LT(share(true), 0.1) << "unmapped: " << share(false);
    EXPECT_GT(share(false), 2 * share(true));
    xdotool("key Escape");
    const CliResult r = view.finish(std::chrono::seconds(60));
    EXPECT_EQ(r.exitCode, 0) << r.err;
}

}  // namespace
}  // namespace cavewall::test
