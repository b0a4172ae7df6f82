#include "config/json_reader.h"
#include "display/projection_stability.h"
#include "walls/stability.h"
#include "display/warp.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "tools/session_args.h"
#ifdef CAVEWALL_HAVE_GL
#include "app/bench/gnuplot.h"
#include "app/bench/gl/driver.h"
#include "app/bench/gl/scale_bench.h"
#endif

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <iostream>

namespace cavewall::tools {

const char* const kBenchUsage =
    "usage: cavewall bench SCENE [--display D] [--path P] [--route walk|wall] [--out DIR] [--frames N] [--resolution "
    "N]\n"
    "                      [--stereo mono|separate] [--mono] [--quick] [--cache DIR] [--compare-every K] [--min-zone "
    "M] [--ppd "
    "N]\n"
    "                      [--bake-resolution N] [--alphas A,B,...] [--warp-alpha A]\n"
    "                      [--lod PX] [--triangle-budget N] [--frame-budget-ms T] [--lod-max PX]\n"
    "                      [--walls flat|depth] [--hierarchy [--hierarchy-budgets T1,T2,...]]\n"
    "                      [--compare-scene OTHER,...] [--on-demand] [--texture-format rgba8|bc1|bc3]\n"
    "                      [--save-worst] [--no-portal-culling]\n"
    "                      [--no-occlusion] [--occlusion-min N] [--occlusion-min-draws D] [--occlusion-min-saved S]\n"
    "       cavewall bench --scale 2M,8M,32M [--data DIR] [--scale-metres M] [--frames N] [--resolution N]\n"
    "                      [--triangle-budget N|near] [--lod-max PX] [--min-zone M] [--walls flat|depth|flat,depth]\n"
    "                      [--display D] [--bake-resolution N] [--geometry-budget MB] [--lod PX] [--compare-every K]\n"
    "                      [--stereo mono|separate] [--mono] [--no-occlusion] [--occlusion-min N]\n"
    "                      [--occlusion-min-draws D] [--occlusion-min-saved S] [--out DIR]\n"
    "       cavewall bench --stability (no other flags)\n"
    "\n"
    "SCENE    error against run time in one run (a scene.json, its folder, or glTF/GLB with\n"
    "         virtual walls). One eye path (the guided navigator along the scene's walkPath,\n"
    "         or with --route wall its wallPath, a second path that hugs the virtual walls;\n"
    "         the head from --path: a tracker spec or a `cavewall run --record` file, default\n"
    "         sim:walk) drives every mode: full geometry (frustum-culled, the reference), cell\n"
    "         culling without textures (the control), the same with one textured full-screen\n"
    "         layer per view (what one wall layer costs), the near-geometry limit (the\n"
    "         viewer's cell plus its walls as bare quads), virtual walls at each of --alphas (default 10,20,30\n"
    "         degrees) with the blend transition, at --warp-alpha (default 20) with the warp\n"
    "         transition and with background paging from a cold start (each alpha planned and\n"
    "         baked into the cache, --cache, default $CAVEWALL_CACHE or ~/.cache/cavewall);\n"
    "         then full geometry, the limit and every blend mode again with levels of detail at\n"
    "         --lod pixels (default 1; 0 leaves these modes out), and every blend mode with\n"
    "         levels of detail under a triangle budget (--triangle-budget, default the median\n"
    "         triangles of the same mode without a budget), and every blend mode with levels of\n"
    "         detail held to --frame-budget-ms (default 16.67, 60 Hz; 0 leaves these out) by the\n"
    "         frame-time controller. Budgets raise the tolerance to at most --lod-max pixels\n"
    "         (default 8). A header line gives the machine's\n"
    "         noise floor: the last mode with each frame followed by one fixed frame, whose\n"
    "         p99/p50 is noise alone.\n"
    "         --walls depth: every walls mode bakes depth with colour and reprojects each wall\n"
    "         pixel to the eye (walls/gl/depth_wall_pass.h); default flat. --walls\n"
    "         flat,depth: depth walls as with --walls depth, and flat walls beside them at every\n"
    "         alpha (blend, and with levels of detail), with their own plan and bake, drawn\n"
    "         frame by frame in turn with the depth walls ('walls flat a=10 blend' beside\n"
    "         'walls depth a=10 blend'): both kinds' times, image and stereo errors in the same seconds.\n"
    "         Every mode culls on the GPU what the depth it has drawn hides, as `cavewall run` does\n"
    "         (each view draws what it saw last frame, then what that depth does not hide; the\n"
    "         same images), full geometry included, in views whose list submits at least\n"
    "         --occlusion-min N triangles (default 100000) in at least --occlusion-min-draws D\n"
    "         draws (default 500), paused for 16 frames in a view where it saved less than\n"
    "         --occlusion-min-saved S of the triangles (default 0.1); triangles a frame are those\n"
    "         drawn. --no-occlusion: none.\n"
    "         Portal culling: the walls modes and the control draw other cells' objects only\n"
    "         where they may be seen through the viewer cell's walls, open boundary and windows\n"
    "         (walls/cell_openings.h); --no-portal-culling draws them whole.\n"
    "         --texture-format: storage of the baked colour (as `cavewall bake`, default\n"
    "         " DEFAULT_TEXTURE_FORMAT
    "); the disk and GPU MB columns and the image error include it.\n"
    "         --hierarchy adds Maciel & Shirley's textured clusters (`cavewall run --hierarchy`)\n"
    "         held to --frame-budget-ms (16.67 when it is 0) by the controller, drawn in turn\n"
    "         with full geometry and the walls modes (impostors made into the cache first);\n"
    "         --hierarchy-budgets 40,60,100 adds one clusters mode per frame time instead. Their\n"
    "         controller (hierarchy/cluster_budget.h) aims the 90th percentile of frame times at the\n"
    "         budget; a figure line per budget gives p95 over the budget, the floor (the\n"
    "         cheapest selection's frame time: a budget below it is infeasible),\n"
    "         predicted against measured frame times and a fit of measured on predicted cost.\n"
    "         --clusters: old name of --hierarchy, kept for one release; likewise\n"
    "         --cluster-budgets of --hierarchy-budgets.\n"
    "         --compare-scene OTHER[,OTHER2...]: scene.json files of the same model\n"
    "         with other cells and walls (e.g. `cavewall walls`'s proposal for SCENE, given its\n"
    "         texture budget): each one's walls are planned and baked at every alpha and drawn in\n"
    "         blend modes (and with levels of detail) on SCENE's eye path, frame by frame in turn\n"
    "         with full geometry and SCENE's walls, labelled with its folder's name ('walls flat\n"
    "         a=10 blend [auto]'); a figure line sets each speed-up against SCENE's same mode.\n"
    "         --on-demand: after the paged mode, walls at --warp-alpha baked on demand\n"
    "         (`cavewall run --bake-on-demand`) from an empty private cache, DIR/on-demand-cache\n"
    "         (emptied first; never the shared --cache): first frame after the scene's load,\n"
    "         geometry fallbacks per frame (bench_frames.csv), textures baked, and frame-time\n"
    "         p99/p50 against the noise floor. Flat walls only.\n"
    "         Per mode: frame, CPU and GPU ms p50/p95/p99, speed-up, the triangles' p99/p50,\n"
    "         triangles, draw calls, textures, texels, disk and GPU MB, and the image error\n"
    "         against full geometry at the same frame, eye and screen, with the worst angular\n"
    "         error in degrees and pixels. Image error: PSNR pooled over all compared pixels\n"
    "         (the figure that the figure lines, the Pareto front and the plot rank by), the\n"
    "         worst frame's PSNR and the 5th percentile of per-frame PSNR; the mean of per-frame\n"
    "         PSNRs capped at 58.9 dB as a labelled column only; RMSE; SSIM (11x11 Gaussian\n"
    "         window); LDR-FLIP mean and share of pixels above 0.1 over all compared pixels\n"
    "         (a percentile reads 0: most pixels match exactly), each image at its screen's\n"
    "         pixels per degree from the frame's head position; popping (peak and RMS) between\n"
    "         consecutive compared frames of each screen; and, against the control 'cells' (no\n"
    "         textures; with levels of detail, the control at the same tolerance), the pooled\n"
    "         PSNR gained and the FLIP mean as a fraction of the control's.\n"
    "         Writes DIR/bench.csv, bench_screens.csv, bench_frames.csv (every timed frame),\n"
    "         bench_compared.csv (every compared image's PSNR and FLIP mean),\n"
    "         bench.md (also printed), bench.png (error against frame time, Pareto front in\n"
    "         red) and flip_worst_N.png (FLIP map of mode N's worst image; --save-worst adds\n"
    "         worst_N.png and worst_N_full.png, that image and full geometry's). Defaults:\n"
    "         display cave4, out bench-out, 120 frames at the display's own resolution (cave4:\n"
    "         1024 x 1024 per screen; --resolution N scales every screen so that its longer\n"
    "         side is N pixels), the display's stereo mode (cave4 and cave6 are stereo; --mono\n"
    "         or --stereo mono: one image per screen; --stereo separate: one image per\n"
    "         eye, every image metric per eye, and the stereo error: per eye and pixel the\n"
    "         disparity error in arc minutes of the eye's depth against full geometry's, mean\n"
    "         and share beyond 1 arcmin), images compared every 4 frames, min-zone 1 m (or the\n"
    "         scene's \"planning\" minZone), 10 pixels per degree, bake textures at most 512\n"
    "         texels (--bake-resolution, or the scene's \"planning\" maxRes). --quick: 24 frames\n"
    "         at 128 pixels (unless --resolution says otherwise), compared every 3, min-zone 3 m,\n"
    "         bakes at most 128 texels. The resolution is printed with every figure.\n"
    "\n"
    "--scale LIST  frame time, resident geometry and time to the first frame against the model's\n"
    "         size: per entry (2M, 500k or 8000000: decimal, k or M, at most 128M, the largest\n"
    "         plant the generator makes) the generated plant (written once into --data\n"
    "         DIR/plant-N, default bench-scale-data, with a stamp, then reused; a folder holding\n"
    "         another model is refused) is walked along the same\n"
    "         first --scale-metres (default 40) of its walk path in --frames frames (default 60)\n"
    "         by full geometry (frustum-culled), the near-geometry limit and virtual walls at\n"
    "         alpha 10 with levels of detail (--lod, default 1 px) and geometry paging\n"
    "         (--geometry-budget, default 64 MB), frame by frame in turn. Only the textures the\n"
    "         stretch's frames request are baked, at most --bake-resolution texels (default\n"
    "         128), into DIR/bake-cache; the report says how many. Writes scale.csv, scale.md\n"
    "         (also printed), scale_ms.png, scale_mb.png and scale_load.png into --out (default\n"
    "         bench-scale-out), with the slopes of full and walls against triangles. Every\n"
    "         --compare-every K frames (default 6, 0: none) the near and walls images are compared\n"
    "         with full geometry's: pooled PSNR, worst frame, FLIP mean, the worst image's FLIP and,\n"
    "         in stereo, the stereo error, beside each size's speed-up.\n"
    "         A fourth mode, walls-budget, draws the walls with their geometry held to\n"
    "         --triangle-budget N triangles a frame (default near: the near limit's median over the\n"
    "         stretch; 0 leaves the mode out), raising the level-of-detail tolerance to at most\n"
    "         --lod-max PX (default 8); its image error shows what the budget costs. --min-zone M\n"
    "         (default: the scene's \"planning\" minZone, else 1) is the walls' smallest zone: a\n"
    "         smaller one narrows the geometry zones near each wall at the cost of more textures.\n"
    "         --walls depth: both walls modes draw depth walls (planned with their own bound,\n"
    "         baked with depth). --walls\n"
    "         flat,depth: flat walls as above and a fifth mode, walls-depth, the walls mode with\n"
    "         depth walls, drawn in turn with the others (depth / flat frame time in one run).\n"
    "         --keep-sheets: depth walls keep the rubber sheets they cut by default (a near\n"
    "         object's colour stretched over the gap beside it), to measure the cut.\n"
    "         Occlusion culling as in a scene's bench (on; --no-occlusion, --occlusion-min,\n"
    "         --occlusion-min-draws, --occlusion-min-saved): triangles a frame are those drawn.\n"
    "\n"
    "--stability  runs the stiff and extreme numerical cases (projection at eye distances\n"
    "             1e-9 ... 1e6 m, world offsets to 1e7 m, near/far ratios to 1e9 with reversed-Z,\n"
    "             1 mm and 1 km screens, the geometry warp's condition as the eye nears a\n"
    "             wall plane, blend weights exactly on zone borders, alpha toward 0 and 90\n"
    "             degrees) and prints, per case, the worst error of a naive float\n"
    "             implementation and of cavewall's path against a long-double reference, the\n"
    "             tolerance and pass/fail. Exit code 1 when any case fails.\n";

namespace {

int runStability() {
    auto rows = display::projectionStability();
    for (auto* cases : {walls::blendBorderCases, walls::alphaExtremeCases})
        for (display::StabilityRow& r : cases()) rows.push_back(std::move(r));
    std::printf("| case | unit | naive float | cavewall | tolerance | warp condition | result |\n");
    std::printf("| --- | --- | ---: | ---: | ---: | ---: | --- |\n");
    int failed = 0;
    for (const auto& r : rows) {
        failed += !r.pass();
        const bool fellBack = r.condition > display::kMaxWarpCondition;
        std::printf("| %s | %s | %s | %s | %s | %s | %s |\n", r.name.c_str(), r.unit.c_str(),
                    std::isnan(r.floatError) ? "–" : config::formatNumber(r.floatError).c_str(),
                    config::formatNumber(r.cavewallError).c_str(), config::formatNumber(r.tolerance).c_str(),
                    r.condition > 0 ? config::formatNumber(r.condition).c_str() : "",
                    !r.pass()  ? "FAIL"
                    : fellBack ? "pass (geometry fallback)"
                               : "pass");
    }
    std::printf("\n%zu cases, %d failed\n", rows.size(), failed);
    return failed ? 1 : 0;
}

#ifdef CAVEWALL_HAVE_GL
// "10,20,30": at least one number, each checked by `check` (which throws on a bad one).
std::vector<double> numberList(const std::string& text, const std::string& what,
                               const std::function<void(double)>& check) {
    std::vector<double> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        out.push_back(parseNumber(text.substr(start, end - start), what));
        check(out.back());
        start = end + 1;
    }
    return out;
}

// "--alphas 10,20,30": angles in (0, 90) degrees.
std::vector<double> alphaList(const std::string& text) {
    return numberList(text, "bench: --alphas", [](double a) {
        if (!(a > 0.0 && a < 90.0))
            throw Error("bench: --alphas: expected angles in (0, 90) degrees, got " + config::formatNumber(a));
    });
}

// "--hierarchy-budgets 40,60,100": frame times in (0, 100000] ms; `flag` names the flag given.
std::vector<double> budgetList(const std::string& text, std::string_view flag) {
    const std::string what = "bench: --" + std::string(flag);
    return numberList(text, what, [&](double ms) {
        if (!(ms > 0.0 && ms <= 1e5))
            throw Error(what + ": expected milliseconds in (0, 100000], got " + config::formatNumber(ms));
    });
}

// The compare scene's label: its folder's name ("auto" for auto/scene.json), letters, digits,
// '_', '-' and '.' kept, anything else '_' (labels go into CSV cells).
std::string compareTag(const std::filesystem::path& scene) {
    const std::filesystem::path absolute = std::filesystem::absolute(scene).lexically_normal();
    const bool file = absolute.has_extension() || std::filesystem::is_regular_file(absolute);
    std::string tag = (file ? absolute.parent_path() : absolute).filename().string();
    if (tag.empty()) tag = (file ? absolute.parent_path().parent_path() : absolute.parent_path()).filename().string();
    for (char& ch : tag)
        if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '_' && ch != '-' && ch != '.') ch = '_';
    return tag.empty() ? "compare" : tag;
}

// "a/scene.json,b/scene.json": at least one path, none empty.
std::vector<std::string> sceneList(const std::string& text) {
    std::vector<std::string> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        out.push_back(text.substr(start, end - start));
        if (out.back().empty())
            throw Error("bench: --compare-scene: expected scene files separated by commas, got an empty entry " +
                        std::to_string(out.size()) + " in '" + text + "'");
        start = end + 1;
    }
    return out;
}

// --stereo mono|separate, and --mono (the same as --stereo mono), on `display`.
void applyStereo(const Args& args, config::DisplayConfig& display) {
    if (auto stereo = args.get("stereo")) {
        if (*stereo == "mono")
            display.stereo = config::StereoMode::Mono;
        else if (*stereo == "separate")
            display.stereo = config::StereoMode::Separate;
        else
            throw Error("bench: --stereo: expected mono or separate, got '" + *stereo + "'");
    }
    applyMono(args, display);
}

int runSceneBench(const Args& args) {
    const bool quick = args.has("quick");
    bench::gl::BenchOptions o;
    o.scene = args.positional(0, "SCENE");
    if (args.positional().size() > 1)
        throw Error("bench: unexpected word '" + args.positional()[1] + "' (expected one SCENE, then --flags)");
    const config::DisplayConfig display = config::loadDisplayConfig(args.getOr("display", "cave4"));
    // The display's own resolution unless asked otherwise: smaller images flatter every mode.
    o.display = display;
    if (quick || args.has("resolution")) {
        const int pixels = static_cast<int>(args.integer("resolution", 128, 16, 4096));
        o.display = bench::gl::withResolution(display, pixels);
    }
    applyStereo(args, o.display);
    if (auto path = args.get("path")) o.tracker = std::filesystem::is_regular_file(*path) ? "replay:" + *path : *path;
    o.route = args.choice("route", app::kRouteNames, app::Route::Walk);
    o.frames = args.integer("frames", quick ? 24 : 120, 1, 100000);
    o.compareEvery = static_cast<int>(args.integer("compare-every", quick ? 3 : 4, 1, 100000));
    o.plan.minZoneSize = args.number("min-zone", quick ? 3.0 : o.plan.minZoneSize, 1e-3, 1e4);
    o.planningGiven.minZone = quick || args.has("min-zone");
    o.plan.pixelsPerDegree = args.number("ppd", o.plan.pixelsPerDegree, 0.01, 1000.0);
    o.bakeResolution = static_cast<int>(args.integer("bake-resolution", quick ? 128 : 512, 16, 16384));
    o.planningGiven.maxRes = quick || args.has("bake-resolution");
    if (auto list = args.get("alphas")) o.alphasDeg = alphaList(*list);
    o.transitionAlphaDeg = args.number("warp-alpha", o.transitionAlphaDeg, 0.1, 89.0);
    o.lodPixels = args.number("lod", o.lodPixels, 0.0, 1e4);
    o.triangleBudget = static_cast<std::size_t>(args.integer("triangle-budget", 0, 0, 1000000000));
    o.frameBudgetMs = args.number("frame-budget-ms", o.frameBudgetMs, 0.0, 1e5);
    o.lodMaxPixels = args.number("lod-max", o.lodMaxPixels, 0.0, 1e4);
    const std::string kinds = args.getOr("walls", "flat");
    if (kinds != "flat" && kinds != "depth" && kinds != "flat,depth")
        throw Error("bench: --walls: expected flat, depth or flat,depth (flat walls beside depth walls), got '" +
                    kinds + "'");
    o.flatBeside = kinds == "flat,depth";
    o.wallKind = kinds == "flat" ? walls::WallKind::Flat : walls::WallKind::Depth;
    o.keepSheets = args.has("keep-sheets");
    o.saveWorst = args.has("save-worst");
    o.occlusion = parseOcclusion(args);
    if (args.has("portal-culling") && args.has("no-portal-culling"))
        throw Error("--portal-culling and --no-portal-culling: expected one of them, got both");
    o.portalCulling = !args.has("no-portal-culling");
    o.textureFormat = args.choice("texture-format", walls::kTextureFormatNames, walls::kDefaultTextureFormat);
    o.clusters = args.has(args.renamed("hierarchy", "clusters"));
    const std::string_view budgets = args.renamed("hierarchy-budgets", "cluster-budgets");
    if (auto list = args.get(budgets)) {
        if (!o.clusters)  // named as the budgets were: old name with old name
            throw Error("bench: --" + std::string(budgets) + " needs --" +
                        (budgets == "cluster-budgets" ? "clusters" : "hierarchy"));
        o.clusterBudgetsMs = budgetList(*list, budgets);
    }
    if (std::find(o.alphasDeg.begin(), o.alphasDeg.end(), o.transitionAlphaDeg) == o.alphasDeg.end()) {
        std::string list;
        for (double a : o.alphasDeg) list += (list.empty() ? "" : ",") + config::formatNumber(a);
        throw Error("bench: --warp-alpha " + config::formatNumber(o.transitionAlphaDeg) +
                    " is not one of the planned alphas (" + list + "); add it to --alphas");
    }
    if (auto cache = args.path("cache")) o.cache = *cache;
    const std::filesystem::path out = args.path("out").value_or("bench-out");
    if (auto list = args.get("compare-scene"))
        for (const std::string& scene : sceneList(*list)) o.compareScenes.push_back({scene, compareTag(scene)});
    if (args.has("on-demand")) o.onDemandCache = out / "on-demand-cache";
    bench::requireGnuplot();  // bench.png needs it: say so before the run, not after it
    const bench::BenchReport report = bench::gl::runBenchmark(o);
    bench::writeReport(out, report);
    std::cout << "\n"
              << bench::markdownReport(report) << "\n"
              << (out / "bench.csv").string() << "\n"
              << (out / "bench.md").string() << "\n"
              << (out / "bench.png").string() << "\n";
    return 0;
}

int runScaleBench(const Args& args) {
    // Flags of the scene bench that the scale bench has no use for: refused, not ignored.
    for (const char* flag : {"quick", "path", "route", "cache", "ppd", "alphas", "warp-alpha", "frame-budget-ms",
                             "keep-sheets", "save-worst", "hierarchy", "clusters", "hierarchy-budgets",
                             "cluster-budgets", "compare-scene", "on-demand", "texture-format"})
        if (args.has(flag))
            throw Error(std::string("bench --scale: --") + flag +
                        " is a flag of `bench SCENE` only (see cavewall "
                        "bench --help), got it with --scale");
    if (!args.positional().empty())
        throw Error("bench --scale: unexpected word '" + args.positional()[0] +
                    "' (the scale bench walks the plants it generates; a SCENE of yours is `bench SCENE`)");
    bench::gl::ScaleOptions o;
    o.sizes = bench::parseScaleList(*args.get("scale"));
    o.data = args.path("data").value_or("bench-scale-data");
    o.display = config::loadDisplayConfig(args.getOr("display", "cave4"));
    if (args.has("resolution"))
        o.display = bench::gl::withResolution(o.display, static_cast<int>(args.integer("resolution", 1024, 16, 4096)));
    applyStereo(args, o.display);
    o.pathMetres = args.number("scale-metres", o.pathMetres, 1.0, 1e5);
    o.frames = args.integer("frames", o.frames, 1, 100000);
    o.bakeResolution = static_cast<int>(args.integer("bake-resolution", o.bakeResolution, 16, 16384));
    o.geometryBudgetMB = args.number("geometry-budget", o.geometryBudgetMB, 0.001, 1e6);
    o.lodPixels = args.number("lod", o.lodPixels, 0.0, 1e4);
    if (const std::optional<std::string> b = args.get("triangle-budget"); b && *b != "near")
        o.triangleBudget = args.integer("triangle-budget", 0, 0, 1000000000);
    o.lodMaxPixels = args.number("lod-max", o.lodMaxPixels, 0.0, 1e4);
    o.compareEvery = static_cast<int>(args.integer("compare-every", o.compareEvery, 0, 100000));
    o.occlusion = parseOcclusion(args);
    o.plan.minZoneSize = args.number("min-zone", o.plan.minZoneSize, 1e-3, 1e4);
    // flat, depth, or both kinds in one run (walls-depth beside the flat walls).
    const std::string kinds = args.getOr("walls", "flat");
    if (kinds == "flat,depth") {
        o.wallKind = walls::WallKind::Flat;
        o.depthBeside = true;
    } else if (kinds == "flat" || kinds == "depth") {
        o.wallKind = kinds == "flat" ? walls::WallKind::Flat : walls::WallKind::Depth;
    } else {
        throw Error("--walls: expected flat, depth or flat,depth (both kinds in one run), got '" + kinds + "'");
    }
    const std::filesystem::path out = args.path("out").value_or("bench-scale-out");
    o.afterSize = [&](const bench::ScaleReport& soFar) { bench::writeScaleReport(out, soFar); };
    bench::requireGnuplot();  // the plots need it: say so before the run, not after it
    const bench::ScaleReport report = bench::gl::runScaleBench(o);
    bench::writeScaleReport(out, report);
    std::cout << "\n"
              << bench::scaleMarkdown(report) << "\n"
              << (out / "scale.csv").string() << "\n"
              << (out / "scale.md").string() << "\n";
    return 0;
}
#endif

}  // namespace

int runBench(const std::vector<std::string>& words) {
    const Args args(words, {"stability", "quick", "hierarchy", "clusters", "on-demand", "keep-sheets", "mono",
                            "occlusion", "no-occlusion", "save-worst", "portal-culling", "no-portal-culling"});
    // One flag list, packed.
    // clang-format off
    args.expectFlags({
        "stability", "quick", "keep-sheets", "mono", "occlusion", "no-occlusion", "occlusion-min", "occlusion-min-draws", "occlusion-min-saved", "display", "path", "route", "out", "frames", "resolution", "stereo", "cache",
        "compare-every", "min-zone", "ppd", "bake-resolution", "alphas", "warp-alpha", "lod",
        "triangle-budget", "frame-budget-ms", "lod-max", "walls", "hierarchy", "hierarchy-budgets", "clusters",
        "cluster-budgets", "compare-scene", "on-demand", "scale", "data", "scale-metres", "geometry-budget",
        "texture-format", "save-worst", "portal-culling", "no-portal-culling"});
    // clang-format on
    // --stability is a bench of its own: with --scale or a SCENE it would silently ignore them.
    args.expectAlone("stability", "bench");
    if (args.has("stability")) return runStability();
#ifdef CAVEWALL_HAVE_GL
    if (args.has("scale")) return runScaleBench(args);
    if (!args.positional().empty()) return runSceneBench(args);
    throw Error("bench: expected a SCENE or --stability (see cavewall bench --help)");
#else
    throw Error("bench: expected --stability (SCENE needs a build with OpenGL; see cavewall bench --help)");
#endif
}

}  // namespace cavewall::tools
