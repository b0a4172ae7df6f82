#include "config/display_config.h"
#include "scenes/generate.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "tools/run_session.h"

#include <cstdlib>
#include <fstream>
#include <iostream>

namespace cavewall::tools {

const char* const kDemoUsage =
    "usage: cavewall demo [--out DIR] [--frames N] [--resolution PX] [--triangles N]\n"
    "\n"
    "The main job: generates the default plant (into $CAVEWALL_CACHE or, without it, cache/\n"
    "beside the cavewall executable), plans and bakes its virtual walls (cached by content),\n"
    "then walks cave4 along the plant's walk path at 5 m/s (along the north aisle from N1 into\n"
    "N3) with the simulated head tracker (sim:walk) for N frames (default 240), once with the\n"
    "walls and once with the full frustum-culled geometry. Each screen renders PX x PX pixels (default\n"
    "256, so the demo finishes in a few minutes on llvmpipe). Prints the median frame time of\n"
    "both runs, the speed-up and the worst angular error, and writes DIR (default demo-out):\n"
    "walls/ and geometry/ (CSV files, frames every 60 frames) and report.md with the fold-outs.\n"
    "Headless without $DISPLAY, windowed otherwise. Walls are planned with alpha 30 degrees,\n"
    "zones of at least 2 m and 2 texels per degree, to keep the bake short (about 660\n"
    "textures: a few minutes on llvmpipe the first time).\n";

namespace {

std::filesystem::path cacheFolder() {
    if (const char* c = std::getenv("CAVEWALL_CACHE"); c && *c) return c;
    std::error_code ec;
    const auto exe = std::filesystem::read_symlink("/proc/self/exe", ec);
    return (ec ? std::filesystem::current_path() : exe.parent_path()) / "cache";
}

std::filesystem::path ensurePlant(const std::filesystem::path& cache, std::size_t triangles) {
    // Generated every time (half a second), never reused from disk: a plant left by an older
    // cavewall would not match this generator. The bake cache is keyed by the files' bytes, so
    // an unchanged plant still bakes nothing.
    const std::filesystem::path dir = cache / ("plant-" + std::to_string(triangles));
    std::cout << "demo: generating the plant (" << triangles << " triangles) in " << dir.string() << "\n";
    scenes::GenerateOptions options;
    options.triangles = triangles;
    scenes::GeneratedScene plant = scenes::generatePlant(options);
    return scenes::writeGenerated(plant, dir);
}

void writeReport(const std::filesystem::path& out, const RunOptions& o, const RunSummary& walls,
                 const RunSummary& geometry) {
    const double mw = median(walls.frameMs), mg = median(geometry.frameMs);
    std::ofstream r(out / "report.md");
    r << "# cavewall demo\n\nThe generated plant on cave4 (" << o.display.screens[0].resolution.x << " x "
      << o.display.screens[0].resolution.y << " pixels per screen), guided along its walk path at " << o.guidePace
      << " m/s with `" << o.tracker << "`, " << o.frames << " frames at 1/60 s, rendered by " << walls.renderer
      << ".\n\n| | walls | full geometry |\n|---|---|---|\n"
      << "| median frame time (ms) | " << mw << " | " << mg << " |\n"
      << "| worst angular error (deg) | " << walls.worstErrorDeg << " | 0 |\n"
      << "| worst angular error (px) | " << walls.worstErrorPx << " | 0 |\n"
      << "| texture page-ins / misses | " << walls.pageIns << " / " << walls.misses << " | - |\n\n"
      << "Speed-up of the median frame time: " << (mw > 0 ? mg / mw : 0.0) << "x (alpha " << o.plan.alphaDeg
      << " deg, " << walls.textures << " textures).\n\nPer-frame data: `walls/frames.csv`, `walls/walls.csv`, "
      << "`geometry/frames.csv`.\n\n## Fold-outs (walls | full geometry)\n\n";
    for (std::size_t i = 0; i < walls.foldouts.size() && i < geometry.foldouts.size(); ++i)
        r << "![walls](" << std::filesystem::relative(walls.foldouts[i], out).string() << ") ![geometry]("
          << std::filesystem::relative(geometry.foldouts[i], out).string() << ")\n\n";
    if (!r) throw Error((out / "report.md").string() + ": cannot write the report");
}

}  // namespace

int runDemo(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"out", "frames", "resolution", "triangles"});
    const std::filesystem::path out = args.getOr("out", "demo-out");
    const std::filesystem::path cache = cacheFolder();
    RunOptions o;
    o.scene = ensurePlant(cache, static_cast<std::size_t>(args.integer("triangles", 2000000, 1000, 100000000)));
    o.display = config::loadDisplayConfig("cave4");
    const int px = static_cast<int>(args.integer("resolution", 256, 16, 4096));
    for (config::Screen& s : o.display.screens) s.resolution = {px, px};
    o.tracker = "sim:walk?seed=1";
    o.frames = args.integer("frames", 240, 1, 1000000);
    o.guidePace = 5.0;
    o.window = WindowMode::Auto;
    o.plan.alphaDeg = 30.0;
    o.plan.minZoneSize = 2.0;
    o.plan.pixelsPerDegree = 2.0;
    o.cache = cache / "bakes";
    o.saveEvery = 60;
    o.verbose = true;

    o.out = out / "walls";
    const RunSummary walls = runSession(o);
    o.out = out / "geometry";
    o.walls = false;
    const RunSummary geometry = runSession(o);
    writeReport(out, o, walls, geometry);
    const double mw = median(walls.frameMs), mg = median(geometry.frameMs);
    std::cout << "demo: median frame time " << mw << " ms with walls, " << mg << " ms full geometry, speed-up "
              << (mw > 0 ? mg / mw : 0.0) << "x; worst error " << walls.worstErrorDeg << " deg ("
              << walls.worstErrorPx << " px)\nGL_RENDERER: " << walls.renderer << "\nreport: "
              << (out / "report.md").string() << "\n";
    return 0;
}

}  // namespace cavewall::tools
