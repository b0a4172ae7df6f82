#include "app/gl/run_session.h"
#include "config/display_config.h"
#include "scenes/generate.h"
#include "display/timing.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <cstdlib>
#include <optional>
#include <fstream>
#include <iostream>

namespace cavewall::tools {

const char* const kDemoUsage =
    "usage: cavewall demo [--out DIR] [--frames N] [--resolution PX] [--triangles N] [--lod PX]\n"
    "\n"
    "The main job: generates the default plant (into $CAVEWALL_CACHE or, without it, cache/\n"
    "beside the cavewall executable), plans and bakes its virtual walls (cached by content),\n"
    "then walks cave4 along the plant's walk path at 5 m/s (along the north aisle from N1 into\n"
    "N3) with the simulated head tracker (sim:walk) for N frames (default 240), three times: with\n"
    "the walls and levels of detail within --lod pixels (default 1; 0: full detail), with the\n"
    "full frustum-culled geometry at the same levels of detail, and with the full geometry at\n"
    "full detail (the reference). Each screen renders PX x PX pixels (default 256, so the demo\n"
    "finishes in a few minutes on llvmpipe). Prints the median frame times, the speed-ups and the\n"
    "worst errors, and writes DIR (default demo-out): walls/, lod/ and geometry/ (CSV files,\n"
    "frames every 60 frames) and report.md with the fold-outs.\n"
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

// One table row: the walls run, the levels-of-detail run (when there is one), the reference.
template <typename A, typename B, typename C>
void row(std::ostream& r, const char* what, const A& walls, const std::optional<B>& lod, const C& geometry) {
    r << "| " << what << " | " << walls;
    if (lod) r << " | " << *lod;
    r << " | " << geometry << " |\n";
}

void writeReport(const std::filesystem::path& out, const app::RunOptions& o, const app::RunSummary& walls,
                 const std::optional<app::RunSummary>& lod, const app::RunSummary& geometry) {
    const double mw = display::median(walls.frameMs), mg = display::median(geometry.frameMs);
    const double ml = lod ? display::median(lod->frameMs) : 0.0;
    auto ifLod = [&](auto value) { return lod ? std::optional(value) : std::nullopt; };
    std::ofstream r(out / "report.md");
    r << "# cavewall demo\n\nThe generated plant on cave4 (" << o.display.screens[0].resolution.x << " x "
      << o.display.screens[0].resolution.y << " pixels per screen), guided along its walk path at " << o.guidePace
      << " m/s with `" << o.tracker << "`, " << o.frames << " frames at 1/60 s, rendered by " << walls.renderer
      << ".\n\n";
    row(r, "", lod ? "walls + levels of detail" : "walls", ifLod("full geometry + levels of detail"), "full geometry");
    row(r, "---", "---", ifLod("---"), "---");
    row(r, "median frame time (ms)", mw, ifLod(ml), mg);
    row(r, "speed-up", mw > 0 ? mg / mw : 0.0, ifLod(ml > 0 ? mg / ml : 0.0), 1);
    row(r, "worst wall texture error (deg)", walls.worstErrorDeg, ifLod("-"), "-");
    row(r, "worst wall texture error (px)", walls.worstErrorPx, ifLod("-"), "-");
    row(r, "worst level-of-detail error (px)", walls.worstLodErrorPx, ifLod(lod ? lod->worstLodErrorPx : 0.0), 0);
    row(r, "texture page-ins / misses", std::to_string(walls.pageIns) + " / " + std::to_string(walls.misses),
        ifLod("-"), "-");
    r << "\nWalls planned at alpha " << o.plan.alphaDeg << " deg (" << walls.textures << " textures)";
    if (o.lodPixels > 0) r << ", levels of detail within " << o.lodPixels << " px";
    r << ". The walls' worst errors are on walls beyond a neighbour drawn as geometry, where the eye is outside "
         "every zone of that cell (`walls/walls.csv` marks them `beyond`).\n\nPer-frame data: `walls/frames.csv`, "
         "`walls/walls.csv`, "
      << (lod ? "`lod/frames.csv`, " : "") << "`geometry/frames.csv`.\n\n## Fold-outs (walls | full geometry)\n\n";
    for (std::size_t i = 0; i < walls.foldouts.size() && i < geometry.foldouts.size(); ++i)
        r << "![walls](" << std::filesystem::relative(walls.foldouts[i], out).string() << ") ![geometry]("
          << std::filesystem::relative(geometry.foldouts[i], out).string() << ")\n\n";
    if (!r) throw Error((out / "report.md").string() + ": cannot write the report");
}

}  // namespace

int runDemo(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"out", "frames", "resolution", "triangles", "lod"});
    const std::filesystem::path out = args.getOr("out", "demo-out");
    const std::filesystem::path cache = cacheFolder();
    app::RunOptions o;
    o.scene = ensurePlant(cache, static_cast<std::size_t>(args.integer("triangles", 2000000, 1000, 40000000)));
    o.display = config::loadDisplayConfig("cave4");
    const int px = static_cast<int>(args.integer("resolution", 256, 16, 4096));
    for (config::Screen& s : o.display.screens) s.resolution = {px, px};
    o.tracker = "sim:walk?seed=1";
    o.frames = args.integer("frames", 240, 1, 1000000);
    o.guidePace = 5.0;
    o.window = app::WindowMode::Auto;
    o.plan.alphaDeg = 30.0;
    o.plan.minZoneSize = 2.0;
    o.plan.pixelsPerDegree = 2.0;
    o.cache = cache / "bakes";
    o.saveEvery = 60;
    o.verbose = true;

    o.lodPixels = args.number("lod", 1.0, 0.0, 1e4);

    auto run = [&](const char* folder, bool walls, double lodPixels) {
        app::RunOptions r = o;
        r.out = out / folder;
        r.walls = walls;
        r.lodPixels = lodPixels;
        return gl::runSession(r);
    };
    const app::RunSummary walls = run("walls", true, o.lodPixels);
    const std::optional<app::RunSummary> lod = o.lodPixels > 0.0 ? std::optional(run("lod", false, o.lodPixels))
                                                            : std::nullopt;
    const app::RunSummary geometry = run("geometry", false, 0.0);
    writeReport(out, o, walls, lod, geometry);
    const double mw = display::median(walls.frameMs), mg = display::median(geometry.frameMs);
    std::cout << "demo: median frame time " << mw << " ms with walls" << (lod ? " and levels of detail" : "") << ", ";
    if (lod) std::cout << display::median(lod->frameMs) << " ms full geometry with levels of detail, ";
    std::cout << mg << " ms full geometry, speed-up " << (mw > 0 ? mg / mw : 0.0) << "x; worst wall error "
              << walls.worstErrorDeg << " deg (" << walls.worstErrorPx << " px), worst level-of-detail error "
              << walls.worstLodErrorPx << " px\nGL_RENDERER: " << walls.renderer << "\nreport: "
              << (out / "report.md").string() << "\n";
    return 0;
}

}  // namespace cavewall::tools
