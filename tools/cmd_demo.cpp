#include "app/bench/demo_front.h"
#include "app/gl/run_session.h"
#include "config/display_config.h"
#include "scenes/file_write.h"
#include "scenes/generate.h"
#include "display/timing.h"
#include "render/occlusion_settings.h"
#include "tools/args.h"
#include "tools/cmd_demo_compare.h"
#include "tools/commands.h"
#include "tools/session_args.h"

#include <cstdlib>
#include <optional>
#include <iostream>
#include <iomanip>
#include <sstream>

namespace cavewall::tools {

const char* const kDemoUsage =
    "usage: cavewall demo [--out DIR] [--frames N] [--resolution PX] [--triangles N] [--lod PX]\n"
    "                     [--texture-format rgba8|bc1|bc3] [--walls depth|flat] [--no-occlusion]\n"
    "\n"
    "The main job: generates the default plant (into $CAVEWALL_CACHE or, without it, cache/\n"
    "beside the cavewall executable), plans and bakes its virtual walls (cached by content),\n"
    "then walks cave4 along the plant's walk path at 10 m/s (along the north aisle from N1 into\n"
    "N3) with the simulated head tracker (sim:walk) for N frames (default 120), four times: with\n"
    "the walls and levels of detail within --lod pixels (default 1; 0: full detail), with the\n"
    "same cells drawn as geometry and no wall textures (the control: what the textures add),\n"
    "with the full frustum-culled geometry at the same levels of detail, and with the full\n"
    "geometry at full detail (the reference). Each screen renders at cave4's own resolution, 1024 x 1024\n"
    "pixels (--resolution PX: PX x PX instead, printed with every figure). Every 30th frame (4\n"
    "frames by default) is saved and compared with the reference: pooled PSNR (all compared\n"
    "pixels together), the worst frame's PSNR and LDR-FLIP (mean and % of pixels above 0.1,\n"
    "each screen at its own pixels per degree from the head). Prints the median frame times, the speed-ups beside "
    "those errors and the\n"
    "worst wall and level-of-detail errors, and writes DIR (default demo-out): walls/, cells/,\n"
    "lod/ and geometry/ (CSV files, the saved frames), worst_frame.png (the frame with the worst\n"
    "FLIP image: walls | full geometry | FLIP map, each as a fold-out) and report.md.\n"
    "Headless without $DISPLAY, windowed otherwise. Walls are planned with alpha 10 degrees\n"
    "(Ebbesmeyer 1997 used 10 and advises at most 15), zones of at least 2 m and 2 texels per\n"
    "degree (depth walls: 1,596 textures, flat walls: 2,142; baked the first time only, then\n"
    "found in the cache by content).\n"
    "--texture-format: storage of the baked wall colour, as for `cavewall bake` (default\n" DEFAULT_TEXTURE_FORMAT
    ").\n"
    "--walls: depth walls by default, as `cavewall run` (the bench's recommended walls mode on\n"
    "the plant, docs/benchmarking.md); --walls flat walks flat walls instead.\n"
    "All four runs cull on the GPU what the depth drawn so far hides, as `cavewall run` does (the\n"
    "same images); --no-occlusion: none.\n"
    "report.md states the resolution, the stereo mode and the machine's load average at the\n"
    "start and the end, applies the bench's rule to the four runs (the recommended walls mode)\n"
    "and embeds their trade-off plot, bench.png, when gnuplot is installed.\n";

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

// One table row: the walls run, the control, the levels-of-detail run (when there is one),
// the reference.
template <typename A, typename D, typename B, typename C>
void row(std::ostream& r, const char* what, const A& walls, const D& control, const std::optional<B>& lod,
         const C& geometry) {
    r << "| " << what << " | " << walls << " | " << control;
    if (lod) r << " | " << *lod;
    r << " | " << geometry << " |\n";
}

// "1024 x 1024 pixels per screen" (the first screen's; cave4's are all alike).
std::string resolutionText(const config::DisplayConfig& d) {
    return std::to_string(d.screens[0].resolution.x) + " x " + std::to_string(d.screens[0].resolution.y) +
           " pixels per screen";
}

std::string errorText(const bench::ImageError& e) {
    std::ostringstream s;
    s << e.psnrDb << " dB pooled (worst frame " << e.worstFramePsnrDb << " dB), FLIP mean " << e.flipMean << " ("
      << 100.0 * e.flipOverThreshold << " % of pixels above " << bench::kFlipThreshold << ")";
    return s.str();
}

struct DemoRuns {
    std::string loadStart, loadEnd;  // /proc/loadavg before the first run and after the comparisons
    app::RunSummary walls, control;
    std::optional<app::RunSummary> lod;
    app::RunSummary geometry;
    DemoComparison wallsError, controlError;
    std::optional<DemoComparison> lodError;
};

std::string kindName(const app::RunOptions& o) { return std::string(walls::wallKindName(o.wallKind)) + " walls"; }

// "32x32 per screen, mono", as the bench states its resolution.
std::string benchResolution(const config::DisplayConfig& d) {
    return std::to_string(d.screens[0].resolution.x) + "x" + std::to_string(d.screens[0].resolution.y) +
           " per screen, " + std::string(config::toString(d.stereo));
}

// The four runs as the bench's modes: full geometry (the reference) first.
bench::BenchReport frontReport(const app::RunOptions& o, const DemoRuns& d) {
    std::vector<bench::DemoMode> modes = {{.medianMs = display::median(d.geometry.frameMs)}};
    if (d.lod && d.lodError)
        modes.push_back({.mode = bench::Mode::Full,
                         .lodPixels = o.lodPixels,
                         .medianMs = display::median(d.lod->frameMs),
                         .error = d.lodError->error});
    modes.push_back({.mode = bench::Mode::Cells,
                     .lodPixels = o.lodPixels,
                     .medianMs = display::median(d.control.frameMs),
                     .error = d.controlError.error,
                     .control = true});
    modes.push_back({.mode = bench::Mode::Walls,
                     .lodPixels = o.lodPixels,
                     .wallKind = o.wallKind,
                     .alphaDeg = o.plan.alphaDeg,
                     .medianMs = display::median(d.walls.frameMs),
                     .error = d.wallsError.error});
    return bench::demoReport(modes, benchResolution(o.display));
}

void writeReport(const std::filesystem::path& out, const app::RunOptions& o, const DemoRuns& d) {
    const double mw = display::median(d.walls.frameMs), mg = display::median(d.geometry.frameMs);
    const double mc = display::median(d.control.frameMs);
    const double ml = d.lod ? display::median(d.lod->frameMs) : 0.0;
    const bench::ImageError& c = d.controlError.error;
    auto ifLod = [&](auto value) { return d.lod ? std::optional(value) : std::nullopt; };
    auto lodError = [&](auto field) { return d.lodError ? std::optional((*d.lodError).error.*field) : std::nullopt; };
    std::ostringstream r;
    r << "# cavewall demo\n\nThe generated plant on cave4 (" << resolutionText(o.display)
      << "), guided along its walk path at " << o.guidePace << " m/s with `" << o.tracker << "`, " << o.frames
      << " frames at 1/60 s, rendered by " << d.walls.renderer << ". Image error: every " << o.saveEvery
      << "th frame against the full geometry's (" << d.wallsError.error.frames << " frames, every screen).\n\n"
      << "- resolution: " << resolutionText(o.display) << "; stereo mode: " << config::toString(o.display.stereo)
      << "\n- walls: " << kindName(o) << " (`--walls " << walls::wallKindName(o.wallKind)
      << "`; the default is the bench's recommended walls mode on the plant, docs/benchmarking.md)"
      << "\n- occlusion culling: "
      << (o.occlusion.on ? render::describe(o.occlusion) + " (all four runs)" : std::string("off (`--no-occlusion`)"))
      << "\n- machine load (/proc/loadavg, 1, 5 and 15 minutes): " << d.loadStart << " at the start, " << d.loadEnd
      << " at the end\n\n";
    const std::string wallsColumn = kindName(o) + (d.lod ? " + levels of detail" : "");
    r << std::setprecision(3);  // three significant digits: what two runs on this machine agree on
    row(r, "", wallsColumn, "control: the same cells, no textures", ifLod("full geometry + levels of detail"),
        "full geometry");
    row(r, "---", "---", "---", ifLod("---"), "---");
    row(r, "median frame time (ms)", mw, mc, ifLod(ml), mg);
    row(r, "speed-up", mw > 0 ? mg / mw : 0.0, mc > 0 ? mg / mc : 0.0, ifLod(ml > 0 ? mg / ml : 0.0), 1);
    row(r, "pooled PSNR (dB)", d.wallsError.error.psnrDb, c.psnrDb, lodError(&bench::ImageError::psnrDb), "inf");
    row(r, "worst frame PSNR (dB)", d.wallsError.error.worstFramePsnrDb, c.worstFramePsnrDb,
        lodError(&bench::ImageError::worstFramePsnrDb), "inf");
    row(r, "FLIP mean", d.wallsError.error.flipMean, c.flipMean, lodError(&bench::ImageError::flipMean), 0);
    auto percent = [](std::optional<double> share) { return share ? std::optional(100.0 * *share) : std::nullopt; };
    row(r, "FLIP > 0.1 (% of pixels)", 100.0 * d.wallsError.error.flipOverThreshold, 100.0 * c.flipOverThreshold,
        percent(lodError(&bench::ImageError::flipOverThreshold)), 0);
    row(r, "worst wall texture error (deg)", d.walls.worstErrorDeg, "-", ifLod("-"), "-");
    row(r, "worst wall texture error (px at its screens' pixels per degree)", d.walls.worstErrorPx, "-", ifLod("-"),
        "-");
    row(r, "worst level-of-detail error (px)", d.walls.worstLodErrorPx, d.control.worstLodErrorPx,
        ifLod(d.lod ? d.lod->worstLodErrorPx : 0.0), 0);
    row(r, "texture page-ins / misses", std::to_string(d.walls.pageIns) + " / " + std::to_string(d.walls.misses), "-",
        ifLod("-"), "-");
    r << "\nThe control draws, frame by frame, the cells the walls draw as geometry (the viewer's cell, "
         "the neighbours in geometry zones and blend strips, structure) and leaves the walls empty: the "
         "walls' image error against the control's is what the textures buy.\n";
    r << "\nWalls planned at alpha " << o.plan.alphaDeg << " deg (" << d.walls.textures << " textures)";
    if (o.lodPixels > 0) r << ", levels of detail within " << o.lodPixels << " px";
    r << ". Every texture drawn is proven within alpha at its eye, the far walls beyond a neighbour drawn as "
         "geometry included (their own beyond zones); `over_alpha` in `walls/frames.csv` counts any that is not "
         "(0 expected).\n\nPer-frame data: `walls/frames.csv`, "
         "`walls/walls.csv`, `cells/frames.csv`, "
      << (d.lod ? "`lod/frames.csv`, " : "") << "`geometry/frames.csv`.\n\n## The trade-off\n\n";
    for (const std::string& line : bench::writeDemoFront(out, frontReport(o, d))) r << line << "\n\n";
    r << "## The worst frame\n\nFrame " << d.wallsError.worstFrame << " (its worst screen's FLIP mean "
      << d.wallsError.worstFlipMean << ", " << resolutionText(o.display)
      << "): walls | full geometry | FLIP map (black 0, pale yellow 1).\n\n![worst frame]("
      << std::filesystem::relative(d.wallsError.foldout, out).string()
      << ")\n\n## Fold-outs (walls | full geometry)\n\n";
    for (std::size_t i = 0; i < d.walls.foldouts.size() && i < d.geometry.foldouts.size(); ++i)
        r << "![walls](" << std::filesystem::relative(d.walls.foldouts[i], out).string() << ") ![geometry]("
          << std::filesystem::relative(d.geometry.foldouts[i], out).string() << ")\n\n";
    scenes::writeBytesAtomically(out / "report.md", r.str());  // checked to its end, like every writer
}

}  // namespace

int runDemo(const std::vector<std::string>& words) {
    const Args args(words, {"mono", "occlusion", "no-occlusion"});
    args.expectFlags({"out", "frames", "resolution", "triangles", "lod", "texture-format", "walls", "mono", "occlusion",
                      "no-occlusion", "occlusion-min", "occlusion-min-draws", "occlusion-min-saved"});
    args.expectNoPositional("demo");
    const std::filesystem::path out = args.getOr("out", "demo-out");
    const std::filesystem::path cache = cacheFolder();
    app::RunOptions o;
    o.scene = ensurePlant(cache, static_cast<std::size_t>(args.integer("triangles", 2000000, 1000, 40000000)));
    o.display = config::loadDisplayConfig("cave4");
    if (args.has("resolution")) {
        const int px = static_cast<int>(args.integer("resolution", 1024, 16, 4096));
        for (config::Screen& s : o.display.screens) s.resolution = {px, px};
    }
    applyMono(args, o.display);
    o.tracker = "sim:walk?seed=1";
    // 120 frames at 10 m/s: the 20 m from N1 into N3, at half the frames a walk at 5 m/s takes,
    // so that the demo stays within 5 minutes on two cores in stereo at 1024 x 1024 per eye.
    o.frames = args.integer("frames", 120, 1, 1000000);
    o.guidePace = 10.0;
    o.window = app::WindowMode::Auto;
    o.plan.alphaDeg = 10.0;
    o.plan.minZoneSize = 2.0;
    o.plan.pixelsPerDegree = 2.0;
    o.cache = cache / "bakes";
    o.saveEvery = 30;
    o.keepSavedImages = true;
    o.verbose = true;
    o.lodPixels = args.number("lod", 1.0, 0.0, 1e4);
    o.textureFormat = args.choice("texture-format", walls::kTextureFormatNames, walls::kDefaultTextureFormat);
    o.wallKind = args.choice("walls", walls::kWallKindNames, o.wallKind);
    o.occlusion = parseOcclusion(args);
    const std::string loadStart = bench::loadAverage();
    std::cout << "demo: cave4 at " << resolutionText(o.display) << ", stereo mode "
              << config::toString(o.display.stereo) << ", " << kindName(o) << " at alpha " << o.plan.alphaDeg
              << " deg; load average " << loadStart << "\n";

    auto run = [&](const char* folder, bool walls, double lodPixels, bool textures = true) {
        app::RunOptions r = o;
        r.out = out / folder;
        r.walls = walls;
        r.wallTextures = textures;
        r.lodPixels = lodPixels;
        return app::gl::runSession(r);
    };
    DemoRuns d{loadStart,
               {},
               run("walls", true, o.lodPixels),
               run("cells", true, o.lodPixels, false),
               std::nullopt,
               {},
               {},
               {},
               std::nullopt};
    if (o.lodPixels > 0.0) d.lod = run("lod", false, o.lodPixels);
    d.geometry = run("geometry", false, 0.0);
    std::cout << "demo: comparing the saved frames with the full geometry's (pooled PSNR, FLIP)\n" << std::flush;
    const display::Display display(o.display);
    d.wallsError = compareRuns(display, d.walls, d.geometry, out);
    d.controlError = compareRuns(display, d.control, d.geometry, out / "cells");
    if (d.lod) d.lodError = compareRuns(display, *d.lod, d.geometry, out / "lod");
    d.loadEnd = bench::loadAverage();
    writeReport(out, o, d);
    const double mw = display::median(d.walls.frameMs), mg = display::median(d.geometry.frameMs);
    std::cout << "demo (" << resolutionText(o.display) << "): median frame time " << mw << " ms with " << kindName(o)
              << (d.lod ? " and levels of detail" : "") << ", ";
    if (d.lod) std::cout << display::median(d.lod->frameMs) << " ms full geometry with levels of detail, ";
    std::cout << mg << " ms full geometry, speed-up " << (mw > 0 ? mg / mw : 0.0) << "x at "
              << errorText(d.wallsError.error)
              << " (the control, the same cells without textures: " << errorText(d.controlError.error)
              << "); worst wall error " << d.walls.worstErrorDeg << " deg (" << d.walls.worstErrorPx
              << " px), worst level-of-detail error " << d.walls.worstLodErrorPx << " px\nload average " << d.loadStart
              << " at the start, " << d.loadEnd << " at the end"
              << "\nGL_RENDERER: " << d.walls.renderer << "\nworst frame: " << d.wallsError.foldout.string()
              << "\nreport: " << (out / "report.md").string() << "\n";
    return 0;
}

}  // namespace cavewall::tools
