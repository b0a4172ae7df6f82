#include "app/bench/display_figure.h"
#include "app/bench/gnuplot.h"
#include "config/display_config.h"
#include "display/display_summary.h"
#include "display/screen_correction.h"
#include "scenes/file_write.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <algorithm>
#include <filesystem>
#include <iostream>
#include <optional>

namespace cavewall::tools {

namespace {

// Reads every screen's warp and blend files as a run would, so that a bad one is found before
// the run: one line per corrected screen. Throws Error naming the screen and the file.
void printCorrections(const config::DisplayConfig& display, const std::string& source) {
    for (std::size_t i = 0; i < display.screens.size(); ++i) {
        const config::Screen& s = display.screens[i];
        const std::string where = source + ": screens[" + std::to_string(i) + "] '" + s.name + "'";
        std::optional<display::ScreenCorrection> c;
        try {
            c = display::loadScreenCorrection(display, static_cast<int>(i));
        } catch (const Error& e) {
            throw Error(where + ": " + e.what());
        }
        if (!c) continue;
        std::cout << "screen " << s.name << " correction:";
        if (!s.warp.empty()) {
            const auto outside = std::count_if(c->warp.nodes.begin(), c->warp.nodes.end(),
                                               [](const display::WarpNode& n) { return !n.valid; });
            std::cout << " warp " << c->warp.width << " x " << c->warp.height << " nodes (" << outside
                      << " outside the projection)";
        }
        if (c->blend)
            std::cout << (s.warp.empty() ? "" : ",") << " blend " << c->blend->width << " x " << c->blend->height
                      << " px";
        std::cout << "\n";
    }
}

}  // namespace

const char* const kDisplayUsage =
    "usage: cavewall display CONFIG [--png FILE] [--size WxH]\n"
    "\n"
    "Checks a display configuration before a run. CONFIG is a file or a preset name (cave4, cave6,\n"
    "powerwall, desktop). Prints a summary: every screen's size in metres, pixels, normal (towards\n"
    "its front side, where the viewer belongs) and the fewest pixels per degree anywhere on it\n"
    "seen from the default head; the stereo mode, near and far planes, the default head (and\n"
    "eyes), the tracking calibration and volume, the edges two screens share, and the area two\n"
    "screens in one plane both cover (a mistake). Each screen's warp and blend files are read as a\n"
    "run reads them, and their sizes printed.\n"
    "--png: also draws the configuration (gnuplot): from the front and from above at one scale,\n"
    "axes in metres, each screen's outline named at its centre with its normal as an arrow, the\n"
    "default head with its view direction, both eyes when stereo, the tracking volume when the\n"
    "configuration sets one, shared edges drawn thick and overlaps filled red, and a legend.\n"
    "--size: the PNG's size in pixels (default 1400x640).\n";

int runDisplay(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"png", "size"});
    const std::string& config = args.positional(0, "CONFIG");
    if (args.positional().size() > 1)
        throw Error("display: expected one CONFIG, got " + std::to_string(args.positional().size()) + " words");
    bench::DisplayFigureOptions options;
    const glm::ivec2 size = args.size("size", 320, 8192).value_or(glm::ivec2(options.width, options.height));
    options.width = size.x;
    options.height = size.y;
    const std::optional<std::filesystem::path> png = args.path("png");
    if (png) scenes::checkWriteTarget(*png, "--png");  // before the work, not after it
    if (png) bench::requireGnuplot();
    const std::filesystem::path source = config::displayConfigPath(config);
    if (png) scenes::checkNotAnInput(*png, "--png", {source});
    const config::DisplayConfig display = config::loadDisplayConfig(config);
    display::printDisplaySummary(std::cout, display, source.string());
    printCorrections(display, source.string());
    if (png) {
        options.legendWidth = std::min(options.legendWidth, options.width / 4);
        bench::writePlot(*png, bench::displayFigure(display, options));
        std::cout << "wrote " << png->string() << "\n";
    }
    return 0;
}

}  // namespace cavewall::tools
