#include "app/bench/gnuplot.h"
#include "app/bench/plan_figure.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "scenes/loader.h"
#include "tools/args.h"
#include "tools/commands.h"
#include "walls/plan.h"
#include "walls/plan_diagram.h"
#include "walls/plan_io.h"
#include "walls/visibility.h"

#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <optional>
#include <sstream>
#include <utility>

namespace cavewall::tools {

const char* const kPlanUsage =
    "usage: cavewall plan SCENE [--alpha DEG] [--json FILE] [--png FILE] [--png-walls FILE]\n"
    "                           [--min-zone M] [--blend M] [--ppd N] [--walls flat|depth]\n"
    "\n"
    "Plans the zones of every virtual wall and portal of SCENE (a scene.json or a folder holding\n"
    "one): geometry, texture and blend zones per cell and wall, with the angular error of every\n"
    "texture proven <= --alpha degrees (default 10) in 3D for every eye in its zones and every\n"
    "scene point behind the wall. The far walls of a neighbour drawn as geometry (from a cell's\n"
    "geometry zone and its blend strip) get zones of their own over those eyes, with the same\n"
    "bound, or are drawn as geometry there. Prints a summary table (zones by kind, textures,\n"
    "texels, memory estimates) and, where cells see each other directly (an edge no wall\n"
    "covers), how many pairs do and the largest such group, drawn whole from any of its cells;\n"
    "writes the plan as JSON (--json, \"beyondZones\" for those far walls) and a top-view\n"
    "diagram (--png: one panel per storey with cells, real and virtual walls and zones by kind,\n"
    "axes in metres and a legend, drawn by gnuplot; --png-walls: one small panel per wall with\n"
    "its zones, sampling points and object footprints).\n"
    "--min-zone: smallest zone width and depth in metres (default: the scene's \"planning\" minZone,\n"
    "else 1; nearer the wall than such a zone can be proven is geometry). --blend: blend strip\n"
    "width in metres (default 0.2).\n"
    "--ppd: texel density target in pixels per degree at each texture's nearest eye (default 10,\n"
    "at most 4096 texels per side), used for the texel and memory estimates.\n"
    "--walls depth: plans depth walls with the depth reprojection's own bound instead of\n"
    "the flat one: per texture, over every eye of its zones, the displacement of any drawn pixel\n"
    "from its surface's true direction: the smaller of a bound from the wall's depth span (nearest\n"
    "to farthest baked box corner behind the plane) and the angle the span's part of a sampling\n"
    "ray subtends at the eye, each with the texel size added (proofs in docs/depth-walls.md). Depth\n"
    "walls keep the flat walls' geometry strip. The JSON's \"textures\" list each texture's bound\n"
    "(maxError, radians) for the kind planned.\n";

namespace {

void writeText(const std::filesystem::path& file, const std::string& text) { scenes::writeBytesAtomically(file, text); }

// The scene's name, else the file's (a folder's own name for "DIR/scene.json").
std::string sceneTitle(const std::filesystem::path& path, const scenes::SceneDescription& description) {
    if (!description.name.empty()) return description.name;
    const std::filesystem::path p = path.filename() == "scene.json" ? path.parent_path() : path;
    return p.filename().empty() ? p.string() : p.filename().string();
}

}  // namespace

int runPlan(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"alpha", "json", "png", "png-walls", "min-zone", "blend", "ppd", "walls"});
    walls::PlanOptions options;
    options.alphaDeg = args.number("alpha", options.alphaDeg, 1e-6, 90.0);
    options.minZoneSize = args.number("min-zone", options.minZoneSize, 0.01, 1000.0);
    options.blendWidth = args.number("blend", options.blendWidth, 0.0, 100.0);
    options.pixelsPerDegree = args.number("ppd", options.pixelsPerDegree, 0.01, 1000.0);
    if (auto kind = args.get("walls")) options.wallKind = walls::parseWallKind(*kind, "--walls");
    walls::validatePlanOptions(options);
    const std::string& path = args.positional(0, "SCENE");
    if (args.positional().size() > 1)
        throw Error("plan: expected one SCENE, got " + std::to_string(args.positional().size()) + " words");
    const std::optional<std::filesystem::path> json = args.path("json"), png = args.path("png"),
                                               pngWalls = args.path("png-walls");
    const auto outputs = {std::pair{json, "--json"}, std::pair{png, "--png"}, std::pair{pngWalls, "--png-walls"}};
    for (const auto& [file, flag] : outputs)
        if (file) scenes::checkWriteTarget(*file, flag);  // before the work, not after it
    if (png) bench::requireGnuplot();
    scenes::SceneDescription description;
    const scenes::Scene scene = scenes::loadSceneFile(path, &description);
    const std::vector<std::filesystem::path> inputs = scenes::sceneInputFiles(path, description);
    for (const auto& [file, flag] : outputs)
        if (file) scenes::checkNotAnInput(*file, flag, inputs);
    walls::useScenePlanning(description, {args.has("min-zone"), false}, options, options.maxResolution);
    const walls::VisibilityTable table = walls::computeVisibility(description);
    const walls::Plan plan = walls::planZones(description, options, walls::wallDepthSpans(scene, description, table));
    for (const std::string& w : scene.warnings) std::cerr << "cavewall: warning: " << w << "\n";
    walls::printPlanSummary(std::cout, plan, description);
    if (const std::string direct = walls::describeDirectGroups(table, description); !direct.empty())
        std::cout << direct << "\n";
    if (json) {
        std::ostringstream text;
        text << std::setprecision(17) << walls::planToJson(plan).dump(1) << "\n";
        writeText(*json, text.str());
        std::cout << "wrote " << json->string() << "\n";
    }
    if (png) {
        bench::writePlot(*png, bench::planFigure(plan, description, sceneTitle(path, description)));
        std::cout << "wrote " << png->string() << "\n";
    }
    if (pngWalls) {
        scenes::writeImage(*pngWalls, walls::planDiagram(plan, description, &scene));
        std::cout << "wrote " << pngWalls->string() << "\n";
    }
    return 0;
}

}  // namespace cavewall::tools
