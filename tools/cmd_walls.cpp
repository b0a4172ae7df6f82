#include "app/bench/gnuplot.h"
#include "app/bench/plan_figure.h"
#include "config/json_reader.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "scenes/scene_description_io.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "walls/auto_walls.h"
#include "walls/plan_diagram.h"
#include "walls/visibility.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>

namespace cavewall::tools {

namespace {
constexpr double kMinSplitMetres = 0.1;  // the smallest chunk --split cuts
}  // namespace

const char* const kWallsUsage =
    "usage: cavewall walls MODEL --out SCENE_JSON [--texture-budget MB] [--alpha DEG] [--max-res N]\n"
    "                      [--ppd N] [--min-zone M] [--min-cell M] [--max-cells N] [--ms-per-mtri MS]\n"
    "                      [--ms-per-wall MS] [--split M] [--rooms] [--keep-paths] [--walk-cost]\n"
    "                      [--plan-limit M] [--png FILE] [--png-walls FILE]\n"
    "\n"
    "Proposes cells and virtual walls for MODEL (a glTF/GLB nobody prepared, or a scene.json or\n"
    "its folder, whose cells and walls are replaced): finds structure (large planes, or the\n"
    "scene's structure node names), the storeys (floors where much upward-facing area lies at one\n"
    "height, each up to the ceiling above it), the walkable rectangle, and tries every\n"
    "grid of cells at least --min-cell metres wide (default 4, at most --max-cells per axis,\n"
    "default 8; each cut moved to where the fewest objects straddle it). Each grid is planned\n"
    "with the zone planner at --alpha (default 10 degrees), --ppd (default 10), --min-zone (metres,\n"
    "default 1, or the input scene's) and --max-res (default 512 texels per side, or the input\n"
    "scene's); the chosen grid has the least expected frame time of a walk over the floor,\n"
    "--ms-per-mtri per million triangles of the viewer's cell (default 150) plus --ms-per-wall\n"
    "per wall side the cell shows (default 5), among those whose textures fit\n"
    "--texture-budget MiB (default 4096; RGBA8 + MIP chain). Writes a valid scene.json (--out;\n"
    "model paths relative to its folder) and a top-view diagram of the proposal's zones\n"
    "(--png: one panel per storey, drawn by gnuplot; --png-walls: one small panel per wall).\n"
    "Prints every candidate, and the largest group of the proposal's cells that see each other\n"
    "directly (drawn whole from any of them). See walls/auto_walls.h for the rules.\n"
    "A model exported as a few huge meshes (a game level, a merged CAD export) has nothing a\n"
    "cell could leave out: when content objects wider than twice --min-cell (with at least 1024\n"
    "triangles each) hold a quarter of the content triangles or more, content objects are first\n"
    "cut into chunks of --split metres (default half of --min-cell and at least 0.1; 0: no\n"
    "cutting), and the proposal's models get \"splitMetres\" so that `run` and `bake` cut them\n"
    "the same way (scenes/mesh_split.h). A model that already has \"splitMetres\" keeps it.\n"
    "A building with real walls (thin vertical structure pieces) gets one more candidate, the\n"
    "rooms: cells cut along the lines of real walls, each doorway a portal (as high as its lintel)\n"
    "and every piece a real wall; --rooms chooses it whatever the cost model says (the model\n"
    "does not count what real walls hide). A building without such lines (walls modelled as many\n"
    "small elements) gets its rooms from each storey's floor plan: wall elements found by their\n"
    "shape, sliced at 0.5 m and 1.2 m above the floor into a 0.1 m grid, gaps up to 1.2 m closed;\n"
    "the floor falls into rooms, the closed gaps between two rooms are doorways (portals) and the\n"
    "rooms are cut into rectangular cells along their walls. Prints the wall elements, rooms,\n"
    "doorways and exits found per storey.\n"
    "A building of several storeys gets cells for each storey on its own (named \"<storey>/<cell>\",\n"
    "with the storey's floorY, its walls from its floor to its ceiling (a virtual wall under a\n"
    "void, such as an atrium, to the ceiling of the storey above), an equal share of\n"
    "--texture-budget each) and one walk path through every storey, up the stairs found.\n"
    "--keep-paths keeps the input scene's walkPath and wallPath instead of the proposal's loop\n"
    "(so that `run` and `bench` walk the same path on both), each point checked to lie in a\n"
    "proposed cell.\n"
    "The proposal records what it was planned with (\"planning\": {\"minZone\": M, \"maxRes\": N}), so\n"
    "that `plan`, `bake`, `run`, `view` and `bench` plan and bake its walls the same way unless\n"
    "given their own --min-zone or --max-res (bench: --bake-resolution). Larger zones mean fewer\n"
    "textures and less disk, drawn as geometry nearer more walls.\n"
    "--walk-cost scores every grid by eyes every 0.25 m along the input's walk path (without\n"
    "one, a 0.5 m grid over the floor), each drawing its cell plus every neighbour whose wall's\n"
    "geometry zone or texture->geometry blend strip holds it, as the walkthrough does (the\n"
    "default counts the viewer's cell only, weighted by floor area). On a long path or a large\n"
    "floor the step widens to keep to 20000 eyes per storey.\n"
    "Planning takes time in proportion to the virtual walls' length (about 4 to 10 textures per\n"
    "metre of wall): grids are planned shortest walls first while their total stays within\n"
    "--plan-limit metres (default 25000, shared among storeys), each within 40 % of it; the rest\n"
    "are listed as not planned. Each candidate is printed on stderr as it is planned.\n"
    "A model with no triangles, with coordinates beyond 100 km of the origin, whose vertices all\n"
    "lie at one point or that has no extent along x or z (no floor) is refused up front.\n";

namespace {

// "storeys: 2 (floors at y 0.00 and 4.60 m)", then a line per storey and the stairs.
void printStoreys(const walls::AutoWallsResult& result) {
    const std::size_t n = result.storeys.size();
    std::string floors;
    for (std::size_t i = 0; i < n; ++i) {
        char y[32];
        std::snprintf(y, sizeof y, "%.2f", result.storeys[i].storey.floorY);
        floors += (i == 0 ? "" : i + 1 == n ? " and " : ", ") + std::string(y);
    }
    std::printf("storeys: %zu (%s at y %s m)\n", n, n == 1 ? "floor" : "floors", floors.c_str());
    for (std::size_t i = 0; i < n; ++i) {
        const walls::AutoWallsStorey& s = result.storeys[i];
        std::printf(
            "storey %zu: floor y %.3f m, ceiling y %.3f m, walkable x [%.2f, %.2f] z [%.2f, %.2f] m, %d cells\n", i,
            s.storey.floorY, s.storey.ceilingY, s.floorMin.x, s.floorMax.x, s.floorMin.y, s.floorMax.y, s.cells);
        std::printf("storey %zu floor plan: %d wall elements, %d rooms (%.0f m²), %d doorways, %d exits\n", i,
                    s.wallElements, s.rooms, s.roomArea, s.doorways, s.exits);
    }
    if (n > 1 && result.stairs.empty())
        std::printf("stairs: none found (the walk path walks each storey on its own)\n");
    for (const walls::Stair& s : result.stairs)
        std::printf(
            "stair: storey %d to %d at x [%.2f, %.2f] z [%.2f, %.2f] m, from (%.2f, %.2f) to (%.2f, %.2f), "
            "%zu turns\n",
            s.from, s.from + 1, s.lo.x, s.hi.x, s.lo.y, s.hi.y, s.bottom.x, s.bottom.y, s.top.x, s.top.y,
            s.path.size() - 2);
    if (n > 1)
        std::printf("virtual walls under a void, raised to the ceiling of the storey above: %d\n", result.wallsRaised);
}

// What the planning limit and the walk cost's eye cap left out (walls/auto_walls_limits.h).
void printLimits(const walls::AutoWallsResult& result, const walls::AutoWallsOptions& options) {
    const walls::AutoWallsLimit& l = result.limit;
    if (l.skipped > 0)
        std::printf(
            "planning limit: %d candidates planned (%.0f m of virtual wall); %d not planned, each with at least "
            "%.0f m of virtual wall, over --plan-limit %.0f m (in all, and %.0f m per candidate): raise "
            "--plan-limit (about 4 to 10 textures per metre to plan), or lower --max-cells, or raise --min-cell\n",
            l.planned, l.plannedMetres, l.skipped, l.skippedMetres, options.planLimitMetres,
            walls::kMostPerCandidate * options.planLimitMetres);
    if (l.eyesWidened)
        std::printf("walk cost: %zu eyes %.2f m apart (widened to keep to %zu per storey)\n", l.eyes, l.eyeStep,
                    walls::kMaxCostEyes);
}

// --rooms is a preference: a storey without rooms within the budget is cut by the cost model's
// choice, and the user is told which and why.
void warnRoomsNotChosen(const walls::AutoWallsResult& result) {
    for (std::size_t i = 0; i < result.storeys.size(); ++i) {
        const walls::AutoWallsStorey& s = result.storeys[i];
        const walls::AutoWallsCandidate& c = result.candidates.at(static_cast<std::size_t>(s.chosen));
        if (c.rooms) continue;
        const bool any = std::any_of(result.candidates.begin(), result.candidates.end(),
                                     [&](const auto& r) { return r.rooms && r.storey == c.storey; });
        std::cerr << "cavewall: warning: --rooms: storey " << i << " is cut by grid " << c.nx << "x" << c.nz
                  << " instead: " << (any ? "its rooms are over the budget" : "no rooms were found")
                  << " (its floor plan: " << s.wallElements << " wall elements, " << s.rooms << " rooms)\n";
    }
}

// The options of `cavewall walls` from its flags.
walls::AutoWallsOptions autoWallsOptions(const Args& args) {
    walls::AutoWallsOptions options;
    options.plan.alphaDeg = args.number("alpha", options.plan.alphaDeg, 1e-6, 90.0);
    options.plan.pixelsPerDegree = args.number("ppd", options.plan.pixelsPerDegree, 0.01, 1000.0);
    options.plan.minZoneSize = args.number("min-zone", options.plan.minZoneSize, 0.01, 1000.0);
    options.plan.maxResolution = static_cast<int>(args.integer("max-res", 512, 16, 16384));
    options.textureBudgetMB = args.number("texture-budget", options.textureBudgetMB, 1e-6, 1e9);
    options.minCellSize = args.number("min-cell", options.minCellSize, 0.1, 1e6);
    options.maxCellsPerAxis = static_cast<int>(args.integer("max-cells", options.maxCellsPerAxis, 1, 26));
    options.msPerMillionTriangles = args.number("ms-per-mtri", options.msPerMillionTriangles, 0.0, 1e9);
    options.msPerWallSide = args.number("ms-per-wall", options.msPerWallSide, 0.0, 1e9);
    options.preferRooms = args.has("rooms");
    options.walkCost = args.has("walk-cost");
    options.planLimitMetres = args.number("plan-limit", options.planLimitMetres, 1.0, 1e9);
    options.progress = [](const std::string& line) { std::cerr << "walls: planned " << line << std::endl; };
    walls::validateAutoWallsOptions(options);
    return options;
}

// When content objects wider than two cells hold a quarter of the content triangles or more,
// cells cannot leave much out: the models get cut into chunks of `split` metres and the scene
// is loaded again.
void splitWideModels(scenes::Scene& scene, scenes::SceneDescription& base, double minCellSize, double split) {
    int widest = 0;
    double wide = 0.0, all = 0.0;
    for (const scenes::Object& o : scene.objects) {
        if (o.role != scenes::Role::Content) continue;
        const glm::dvec3 size = o.worldBounds.size();
        const auto triangles = static_cast<double>(scene.meshes[o.mesh].triangleCount());
        all += triangles;
        if (std::max(size.x, size.z) > 2.0 * minCellSize && triangles >= 1024) {
            ++widest;
            wide += triangles;
        }
    }
    if (widest > 0 && wide >= 0.25 * all) {
        int models = 0;
        for (scenes::ModelFile& m : base.models)
            if (m.splitMetres <= 0.0) {
                m.splitMetres = split;
                ++models;
            }
        if (models > 0) {
            const std::size_t before = scene.objects.size();
            scene = scenes::loadScene(base);
            std::printf(
                "split: %d content object(s) wider than %.1f m hold %.0f %% of the content triangles; "
                "models cut into chunks of %.2f m: %zu objects -> %zu (\"splitMetres\" in the proposal)\n",
                widest, 2.0 * minCellSize, 100.0 * wide / all, split, before, scene.objects.size());
        }
    }
}

// The candidates' table, storey by storey, the chosen ones marked.
void printCandidates(const walls::AutoWallsResult& result) {
    std::printf("%-7s %6s %12s %16s %9s %12s %7s\n", "grid", "cells", "expected ms", "cell triangles", "textures",
                "texture MiB", "budget");
    for (std::size_t i = 0; i < result.candidates.size(); ++i) {
        const walls::AutoWallsCandidate& c = result.candidates[i];
        if (result.storeys.size() > 1 && (i == 0 || result.candidates[i - 1].storey != c.storey))
            std::printf("storey %d:\n", c.storey);
        const bool chosen =
            std::any_of(result.storeys.begin(), result.storeys.end(),
                        [&](const walls::AutoWallsStorey& s) { return s.chosen == static_cast<int>(i); });
        const std::string grid = c.rooms ? "rooms" : std::to_string(c.nx) + "x" + std::to_string(c.nz);
        const std::string cut = c.floorPlan ? std::to_string(c.nx) + " rectangles along the floor plan's rooms"
                                            : std::to_string(c.nx) + " x " + std::to_string(c.nz) + " along real walls";
        const std::string rooms = c.rooms ? "  (" + cut + ": " + std::to_string(c.portals) + " portals, " +
                                                std::to_string(c.virtualWalls) + " virtual walls)"
                                          : "";
        std::printf("%-7s %6d %12.1f %16.0f %9d %12.1f %7s%s%s\n", grid.c_str(), c.nx * c.nz, c.expectedMs,
                    c.meanCellTriangles, c.textures, c.textureMB, c.withinBudget ? "fits" : "over",
                    chosen ? "  <- chosen" : "", rooms.c_str());
    }
}

// Model paths relative to the folder of the scene.json written to `out`.
void relocateModels(walls::AutoWallsResult& result, const scenes::SceneDescription& base,
                    const std::filesystem::path& out) {
    const std::filesystem::path outFolder = std::filesystem::absolute(out).parent_path();
    for (scenes::ModelFile& m : result.description.models)
        m.file = std::filesystem::relative(std::filesystem::absolute(base.folder / m.file), outFolder);
    result.description.folder = outFolder;
}

// The proposal's plan figure (--png) and per-wall diagram (--png-walls).
void writeFigures(const walls::AutoWallsResult& result, const scenes::Scene& scene, const std::string& model,
                  const walls::PlanOptions& planOptions, const std::optional<std::filesystem::path>& png,
                  const std::optional<std::filesystem::path>& pngWalls) {
    const walls::Plan plan = walls::planZones(result.description, planOptions);
    if (png) {
        bench::writePlot(*png, bench::planFigure(plan, result.description,
                                                 std::filesystem::path(model).stem().string() + ", proposed"));
        std::cout << "wrote " << png->string() << "\n";
    }
    if (pngWalls) {
        scenes::writeImage(*pngWalls, walls::planDiagram(plan, result.description, &scene, 200));
        std::cout << "wrote " << pngWalls->string() << "\n";
    }
}

}  // namespace

int runWalls(const std::vector<std::string>& words) {
    const Args args(words, {"rooms", "keep-paths", "walk-cost"});
    args.expectFlags({"out", "texture-budget", "alpha", "max-res", "ppd", "min-zone", "min-cell", "max-cells",
                      "ms-per-mtri", "ms-per-wall", "split", "rooms", "keep-paths", "walk-cost", "plan-limit", "png",
                      "png-walls"});
    walls::AutoWallsOptions options = autoWallsOptions(args);
    const std::string& path = args.positional(0, "MODEL");
    if (args.positional().size() > 1)
        throw Error("walls: expected one MODEL, got " + std::to_string(args.positional().size()) + " words");
    const std::filesystem::path out = args.require("out");
    const std::optional<std::filesystem::path> png = args.path("png"), pngWalls = args.path("png-walls");
    scenes::checkWriteTarget(out, "--out");  // before the work, not after it
    if (png) scenes::checkWriteTarget(*png, "--png");
    if (pngWalls) scenes::checkWriteTarget(*pngWalls, "--png-walls");
    if (png) bench::requireGnuplot();

    // The default, half of --min-cell, is held to the smallest chunk (a --min-cell of 0.1 m
    // cuts into 0.1 m chunks): only a --split the user gives can be refused for its size.
    const double split = args.number("split", std::max(kMinSplitMetres, options.minCellSize / 2.0), 0.0, 1e6);
    if (split > 0.0 && split < kMinSplitMetres)
        throw Error("--split: expected 0 (no cutting) or at least 0.1 metres, got " + config::formatNumber(split));

    scenes::SceneDescription base;
    scenes::Scene scene = scenes::loadSceneFile(path, &base);
    walls::checkWallsModel(scene, path);
    walls::useScenePlanning(base, {args.has("min-zone"), args.has("max-res")}, options.plan,
                            options.plan.maxResolution);
    const std::vector<std::filesystem::path> inputs = scenes::sceneInputFiles(path, base);
    scenes::checkNotAnInput(out, "--out", inputs);
    if (png) scenes::checkNotAnInput(*png, "--png", inputs);
    if (pngWalls) scenes::checkNotAnInput(*pngWalls, "--png-walls", inputs);
    if (split > 0.0) splitWideModels(scene, base, options.minCellSize, split);
    for (const std::string& w : scene.warnings) std::cerr << "cavewall: warning: " << w << "\n";
    std::vector<std::string> warnings;
    walls::AutoWallsResult result = walls::proposeWalls(scene, base, options, &warnings);
    for (const std::string& w : warnings) std::cerr << "cavewall: warning: " << w << "\n";

    relocateModels(result, base, out);
    // What the proposal was planned with, for every command that plans or bakes it later.
    result.description.planning = {options.plan.minZoneSize, options.plan.maxResolution};
    if (args.has("keep-paths")) {
        if (base.walkPath.empty()) throw Error("walls: --keep-paths: expected a walkPath in " + path + ", got none");
        result.description.walkPath = base.walkPath;
        result.description.wallPath = base.wallPath;
        scenes::validateSceneDescription(result.description,
                                         out.string() + " (--keep-paths: the paths of " + path + ")");
    }

    printStoreys(result);
    std::printf("%zu structure objects\n", result.structure.size());
    printCandidates(result);
    printLimits(result, options);
    if (options.preferRooms) warnRoomsNotChosen(result);
    if (const auto& g = result.given)
        std::printf("%-7s %6zu %12.1f %16.0f %9d %12.1f %7s  (the input's own cells and walls)\n", "given",
                    base.cells.size(), g->expectedMs, g->meanCellTriangles, g->textures, g->textureMB,
                    g->withinBudget ? "fits" : "over");
    scenes::writeBytesAtomically(out, scenes::writeSceneDescription(result.description));
    std::size_t portals = 0;
    for (const scenes::VirtualWall& w : result.description.walls) portals += w.kind == scenes::WallKind::Portal;
    std::cout << "wrote " << out.string() << " (" << result.description.cells.size() << " cells, "
              << result.description.walls.size() - portals << " virtual walls, " << portals
              << " portals), planned with zones of at least "
              << config::formatNumber(result.description.planning.minZone) << " m and textures of at most "
              << result.description.planning.maxRes
              << " texels (its \"planning\", which plan, bake, run, view and bench follow)\n";
    const std::string direct =
        walls::describeDirectGroups(walls::computeVisibility(result.description), result.description);
    if (!direct.empty()) std::cout << direct << "\n";
    if (png || pngWalls) writeFigures(result, scene, path, options.plan, png, pngWalls);
    return 0;
}

}  // namespace cavewall::tools
