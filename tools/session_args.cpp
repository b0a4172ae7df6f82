#include "tools/session_args.h"

#include "app/interrupt.h"
#include "config/json_reader.h"
#include "display/timing.h"
#include "walls/cache_budget.h"

#include <algorithm>
#include <cstdio>
#include <iostream>

namespace cavewall::tools {
namespace {

long saveEvery(const std::string& spec) {
    if (spec == "none") return 0;
    if (spec == "all") return 1;
    if (spec.rfind("every:", 0) == 0) {
        const double k = parseNumber(std::string_view(spec).substr(6), "--save-frames every:K");
        if (k >= 1 && k <= 1e9 && k == static_cast<long>(k)) return static_cast<long>(k);
    }
    throw Error("--save-frames: expected none, all or every:K with an integer K >= 1, got '" + spec + "'");
}

std::string seconds(double s) { return config::formatFixed(s, 3); }

std::string geometryLine(std::string_view command, const app::RunSummary& s) {
    char text[256];
    std::snprintf(text, sizeof text,
                  ": geometry paging: at most %.2f MB resident (largest three cells %.2f MB, whole model %.2f MB) "
                  "besides %.2f MB always resident; page-ins %ld, misses %ld, cells drawn unloaded %ld\n",
                  s.geometryPeakMB, s.largestThreeCellsMB, s.modelGeometryMB, s.sharedGeometryMB, s.geometryPageIns,
                  s.geometryMisses, s.geometryForced);
    return std::string(command) + text;
}

std::string bakeLine(std::string_view command, const app::RunSummary& s) {
    char text[320];
    std::snprintf(text, sizeof text,
                  ": baking on demand: %d textures missing at the start, %d baked during the run, %d still "
                  "missing; first frame %.2f s after the scene loaded",
                  s.texturesMissingAtStart, s.texturesBaked, s.texturesStillMissing,
                  s.firstFrameSeconds - s.sceneSeconds);
    std::string line = std::string(command) + text;
    if (s.cacheEvictions > 0 || s.cacheMB > 0.0) {
        std::snprintf(text, sizeof text, "; cache %.1f MB, %ld files evicted", s.cacheMB, s.cacheEvictions);
        line += text;
    }
    for (const std::string& w : s.bakeWarnings) line += "\n" + std::string(command) + ": warning: " + w;
    return line + "\n";
}

std::string clustersLine(std::string_view command, const app::RunSummary& s) {
    char text[400];
    std::snprintf(text, sizeof text,
                  ": clusters: %d (%d made, %d from the cache) in %.2f s; measured costs at %dx%d: %.3g ms per "
                  "triangle, %.3g ms per object, %.3g ms per textured box plus %.3g ms per whole view it covers, "
                  "%.3g ms per average box plus %.3g ms per whole view\n",
                  s.clusters, s.clustersMade, s.clustersReused, s.clustersSeconds, s.costResolution, s.costResolution,
                  s.msPerTriangle, s.msPerObject, s.texturedBoxMs, s.texturedViewMs, s.averageBoxMs, s.averageViewMs);
    return std::string(command) + text;
}

// The rendering, navigation and output flags.
void parseDrawing(const Args& args, app::RunOptions& o) {
    o.transition = args.choice("transition", app::kTransitionNames, o.transition);
    o.walls = !args.has("no-walls");
    o.wallTextures = !args.has("no-textures");
    o.portalCulling = !args.has("no-portal-culling");
    o.wallKind = args.choice("walls", walls::kWallKindNames, o.wallKind);
    o.textureFormat = args.choice("texture-format", walls::kTextureFormatNames, walls::kDefaultTextureFormat);
    o.plan.alphaDeg = args.number("alpha", o.plan.alphaDeg, 1e-3, 90.0);
    o.plan.minZoneSize = args.number("min-zone", o.plan.minZoneSize, 1e-3, 1e4);
    o.planningGiven.minZone = args.has("min-zone");
    o.plan.pixelsPerDegree = args.number("ppd", o.plan.pixelsPerDegree, 0.01, 1000.0);
    if (auto c = args.path("cache")) o.cache = *c;
    o.textureBudgetMB = args.number("budget", o.textureBudgetMB, 1e-3, 1e6);
    o.geometryBudgetMB = args.number("geometry-budget", 0.0, 0.0, 1e6);
    o.bakeResolution = static_cast<int>(args.integer("max-res", o.bakeResolution, 16, 16384));
    o.planningGiven.maxRes = args.has("max-res");
    o.synchronousPaging = args.has("sync-paging");
    o.lodPixels = args.number("lod", o.lodPixels, 0.0, 1e4);
    o.triangleBudget = static_cast<std::size_t>(args.integer("triangle-budget", 0, 0, 1000000000));
    o.frameBudgetMs = args.number("frame-budget-ms", 0.0, 0.0, 1e5);
    o.lodMaxPixels = args.number("lod-max", o.lodMaxPixels, 0.0, 1e4);
}

// Baking on demand and the two kinds of cluster.
void parseBakingAndClusters(const Args& args, app::RunOptions& o) {
    if (args.has("bake-on-demand") && args.has("bake-first"))
        throw Error("--bake-on-demand and --bake-first: expected one of them, got both");
    o.clusters = args.has(args.renamed("hierarchy", "clusters"));
    o.cluster = args.has("cluster");
    // A session that runs until stopped is a person at the controls: it draws at once and bakes
    // what the cache lacks while walking, unless told to bake first or asked for what baking on
    // demand cannot do. Runs of N frames keep their reproducible default.
    const bool interactive =
        o.frames == 0 && !args.has("bake-first") && !o.synchronousPaging && !o.cluster && o.wallTextures && !o.clusters;
    o.bakeOnDemand = args.has("bake-on-demand") || interactive;
    o.bakeInterleave = args.integer("bake-interleave", 0, 0, 1000000);
    o.bakeNice = static_cast<int>(args.integer("bake-nice", o.bakeNice, 0, 19));
    if (auto budget = args.get("cache-budget")) o.cacheBudgetMB = parseNumber(*budget, "--cache-budget");
    if (args.has("cache-budget")) walls::cacheBudgetBytes(o.cacheBudgetMB, "--cache-budget");
    o.clusterDivisions = static_cast<int>(
        args.integer(args.renamed("hierarchy-divisions", "cluster-divisions"), o.clusterDivisions, 1, 1024));
    o.clusterResolution =
        static_cast<int>(args.integer(args.renamed("hierarchy-res", "cluster-res"), o.clusterResolution, 4, 2048));
    o.clusterFadeFrames =
        static_cast<int>(args.integer(args.renamed("hierarchy-fade", "cluster-fade"), o.clusterFadeFrames, 0, 600));
    o.clusterTimeout = args.number("cluster-timeout", o.clusterTimeout, 0.1, 3600.0);
}

}  // namespace

Args sessionArgs(const std::vector<std::string>& words) {
    return Args(words,
                {"headless", "window", "no-walls", "no-textures", "sync-paging", "cluster", "hierarchy", "clusters",
                 "bake-on-demand", "bake-first", "save-window", "mono", "keep-sheets", "occlusion", "no-occlusion",
                 "no-portal-culling"});
}

render::OcclusionSettings parseOcclusion(const Args& args) {
    if (args.has("occlusion") && args.has("no-occlusion"))
        throw Error("--occlusion and --no-occlusion: expected one of them, got both");
    render::OcclusionSettings s;
    s.on = !args.has("no-occlusion");
    s.minTriangles =
        static_cast<std::size_t>(args.integer("occlusion-min", static_cast<long>(s.minTriangles), 0, 1000000000));
    s.minDraws =
        static_cast<std::size_t>(args.integer("occlusion-min-draws", static_cast<long>(s.minDraws), 0, 1000000000));
    s.minSavedShare = args.number("occlusion-min-saved", s.minSavedShare, 0.0, 1.0);
    return s;
}

std::vector<std::string_view> sessionFlags() {
    // One flag list, packed.
    // clang-format off
    return {
        "display", "tracker", "frames", "nav", "pace", "route", "start", "headless", "window", "transition",
        "no-walls", "no-textures", "alpha", "min-zone", "ppd", "save-frames", "save-window", "record", "cache",
        "budget", "geometry-budget", "max-res", "sync-paging", "out", "cluster", "cluster-timeout", "lod",
        "triangle-budget", "frame-budget-ms", "lod-max", "walls", "hierarchy", "hierarchy-divisions",
        "hierarchy-res", "hierarchy-fade", "clusters", "cluster-divisions", "cluster-res", "cluster-fade",
        "bake-on-demand", "bake-first", "cache-budget", "bake-interleave", "bake-nice", "texture-format",
        "texture-max", "texture-budget", "resolution", "mono", "keep-sheets", "occlusion", "no-occlusion",
        "occlusion-min", "occlusion-min-draws", "occlusion-min-saved", "no-portal-culling"};
    // clang-format on
}

void applyMono(const Args& args, config::DisplayConfig& display) {
    if (!args.has("mono")) return;
    if (auto stereo = args.get("stereo"); stereo && *stereo != "mono")
        throw Error("--mono and --stereo " + *stereo + ": expected one stereo mode, got both");
    display.stereo = config::StereoMode::Mono;
}

scenes::TextureLimits parseTextureLimits(const Args& args) {
    scenes::TextureLimits limits;
    limits.maxSide = static_cast<int>(args.integer("texture-max", limits.maxSide, 1, 16384));
    limits.budgetBytes = static_cast<std::size_t>(
                             args.integer("texture-budget", static_cast<long>(limits.budgetBytes >> 20), 1, 1048576))
                         << 20;
    return limits;
}

app::RunOptions parseSessionOptions(const Args& args, app::RunOptions o) {
    if (args.has("headless") && args.has("window"))
        throw Error("--headless and --window: expected one of them, got both");
    if (auto display = args.get("display")) o.display = config::loadDisplayConfig(*display);
    if (const std::optional<glm::ivec2> pixels = args.size("resolution", 1, 16384))
        for (config::Screen& screen : o.display.screens) screen.resolution = *pixels;
    applyMono(args, o.display);
    o.keepSheets = args.has("keep-sheets");
    o.occlusion = parseOcclusion(args);
    o.tracker = args.getOr("tracker", o.tracker);
    o.frames = args.integer("frames", o.frames, 0, 10000000);
    o.out = args.getOr("out", o.out.string());
    o.nav = args.choice("nav", app::kNavigationNames, o.nav);
    o.guidePace = args.number("pace", o.guidePace, 0.0, 100.0);
    o.route = args.choice("route", app::kRouteNames, o.route);
    o.start = args.choice("start", app::kStartNames, o.start);
    if (args.has("window")) o.window = app::WindowMode::Window;
    if (args.has("headless")) o.window = app::WindowMode::Headless;
    if (auto r = args.get("record")) o.record = *r;
    o.saveEvery = saveEvery(args.getOr("save-frames", "none"));
    o.saveWindow = args.has("save-window");
    parseDrawing(args, o);
    parseBakingAndClusters(args, o);
    o.sceneTextures = parseTextureLimits(args);
    app::validate(o);
    return o;
}

int reportSession(std::string_view command, const app::RunOptions& o, const app::RunSummary& s) {
    if (s.rank != 0) return 0;
    const std::string c(command);
    if (s.frameMs.empty()) {
        std::cout << c << ": stopped before the first frame: " << app::toString(s.ending) << " (scene loaded at "
                  << seconds(s.sceneSeconds) << " s, stopped at " << seconds(s.wallsSeconds) << " s)\n";
        if (!o.out.empty()) std::cout << (o.out / "frames.csv").string() << "\n";
        const int signal = s.ending == app::Ending::Interrupted ? app::interruptSignal() : 0;
        return signal != 0 ? 128 + signal : 0;
    }
    const double worst = *std::max_element(s.frameMs.begin(), s.frameMs.end());
    const double worstAfterFirst =
        s.frameMs.size() > 1 ? *std::max_element(s.frameMs.begin() + 1, s.frameMs.end()) : worst;
    std::cout << c << ": " << s.frameMs.size() << " frames on " << s.renderer
              << (!s.walls         ? ", geometry only"
                  : o.wallTextures ? ", walls"
                                   : ", the control (the walls' cells, no textures)")
              << "; median frame " << config::formatFixed(display::median(s.frameMs), 1) << " ms, worst "
              << config::formatFixed(worst, 1) << " ms (after the first " << config::formatFixed(worstAfterFirst, 1)
              << " ms); worst error " << config::formatFixed(s.worstErrorDeg, 2) << " deg ("
              << config::formatFixed(s.worstErrorPx, 1) << " px); page-ins " << s.pageIns << ", misses " << s.misses
              << (s.checkFailures > 0
                      ? ", " + std::to_string(s.checkFailures) + " textures refused by the content check"
                      : std::string())
              << "\n"
              << c << ": first frame after " << seconds(s.firstFrameSeconds) << " s (scene loaded at "
              << seconds(s.sceneSeconds) << " s, walls ready at " << seconds(s.wallsSeconds)
              << " s, walkthrough ready at " << seconds(s.readySeconds) << " s)\n"
              << (o.geometryBudgetMB > 0.0 && s.walls ? geometryLine(command, s) : std::string())
              << (o.clusters ? clustersLine(command, s) : std::string())
              << (o.bakeOnDemand && s.walls ? bakeLine(command, s) : std::string());
    if (s.ending != app::Ending::Frames)
        std::cout << c << ": stopped after " << s.frameMs.size() << " frames: " << app::toString(s.ending) << "\n";
    if (!o.out.empty()) std::cout << (o.out / "frames.csv").string() << "\n";
    const int signal = s.ending == app::Ending::Interrupted ? app::interruptSignal() : 0;
    return signal != 0 ? 128 + signal : 0;
}

}  // namespace cavewall::tools
