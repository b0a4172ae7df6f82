#include "config/error.h"
#include "scenes/generate.h"
#include "scenes/glb_writer.h"
#include "scenes/obj_writer.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <iostream>

namespace cavewall::tools {

const char* const kGenerateUsage =
    "usage: cavewall generate plant|house|boxes --out DIR [--seed N] [--triangles N]\n"
    "\n"
    "Writes DIR/<plant|house>.glb (glTF 2.0, opens in any viewer) and DIR/scene.json (cells,\n"
    "virtual walls or portals, real walls, walk path), deterministically from --seed (default 0):\n"
    "the same seed gives the same bytes. --triangles sets the minimum number of drawn triangles\n"
    "(default: 2000000 for the plant, 200000 for the house; at most 128000000). The plant's round\n"
    "parts are refined up to a CAD export's chordal deviation of 1 mm (smaller targets get coarser\n"
    "ones); beyond that its machines, robots, conveyors, cabinets and pipe racks gain parts\n"
    "(bolts, buttons, tool holders, cable links, rollers, valves, vents), as large CAD models do.\n"
    "From 3000000 on the plant grows longer instead: 8 bays of 10 m per 2000000 triangles, so a\n"
    "cell holds about the same geometry at every size (parts of one kind share a mesh, as a CAD\n"
    "export's assemblies do). The house's round parts follow the target, up to its most detailed\n"
    "level (a larger target is an error). Prints a summary and, as its last line, the scene.json\n"
    "path.\n"
    "  plant  an 80 m x 40 m production hall cut by 37 virtual walls into 24 cells (rows N, M, S\n"
    "         of 8 cells 10 m wide; the walk path runs along the aisles in rows N and S); longer\n"
    "         for larger targets (32000000: 1.28 km, 384 cells)\n"
    "  house  six rooms with real walls; every doorway is a portal, every room a cell\n"
    "  boxes  a 60 m x 8 m x 30 m hall of random axis-aligned boxes (24 vertices, 12 triangles\n"
    "         each, per-face normals, one mesh, one primitive; default 1000000 triangles) for\n"
    "         comparing draw paths with other viewers: writes DIR/boxes.glb and DIR/boxes.obj\n"
    "         (the same mesh for OBJ readers such as osgconv), no scene.json; the last line\n"
    "         printed is the .glb path (`cavewall draw-bench` takes it)\n";

namespace {

int writeBoxHall(const scenes::GenerateOptions& options, const std::filesystem::path& dir) {
    const scenes::Scene scene = scenes::generateBoxHall(options);
    scenes::writeGlb(scene, dir / "boxes.glb");
    scenes::writeObj(scene, dir / "boxes.obj");
    const scenes::Bounds b = scene.bounds();
    std::cout << "boxes: " << scene.meshes[0].positions.size() / 24 << " boxes, " << scene.triangleCount()
              << " triangles, bounds [" << b.min.x << ", " << b.min.y << ", " << b.min.z << "] .. [" << b.max.x << ", "
              << b.max.y << ", " << b.max.z << "] m\n"
              << (dir / "boxes.obj").string() << "\n"
              << (dir / "boxes.glb").string() << "\n";
    return 0;
}

}  // namespace

int runGenerate(const std::vector<std::string>& words) {
    const Args args(words, {});
    args.expectFlags({"out", "seed", "triangles"});
    const std::string kind = args.positional(0, "the scene kind (plant, house or boxes)");
    if (args.positional().size() > 1)
        throw Error("generate: unexpected argument '" + args.positional()[1] +
                    "' (expected only plant, house or boxes)");
    if (kind != "plant" && kind != "house" && kind != "boxes")
        throw Error("generate: unknown scene kind '" + kind + "' (expected plant, house or boxes)");
    scenes::GenerateOptions options;
    options.seed = static_cast<std::uint64_t>(args.integer("seed", 0, 0, 2147483647L));
    // The plant grows by 10 m bays (8 per 2 M triangles, up to 512 bays: about 128 M drawn);
    // larger targets could not be met, so they are refused. The house grows by detail only.
    options.triangles =
        static_cast<std::size_t>(args.integer("triangles", 0, 0, static_cast<long>(scenes::kPlantMaxTriangles)));
    if (kind == "boxes") return writeBoxHall(options, args.require("out"));
    scenes::GeneratedScene g = kind == "plant" ? scenes::generatePlant(options) : scenes::generateHouse(options);
    if (g.scene.triangleCount() < options.triangles)
        throw Error("--triangles: the " + kind + " reaches at most " + std::to_string(g.scene.triangleCount()) +
                    " drawn triangles (its most detailed level), got a target of " + std::to_string(options.triangles));
    const auto json = scenes::writeGenerated(g, args.require("out"));
    std::size_t unique = 0;
    for (const auto& m : g.scene.meshes) unique += m.triangleCount();
    std::cout << kind << ": " << g.scene.objects.size() << " objects, " << g.scene.meshes.size() << " meshes, "
              << g.scene.triangleCount() << " triangles drawn (" << unique << " stored), " << g.description.cells.size()
              << " cells, " << g.description.walls.size() << " " << (kind == "plant" ? "virtual walls" : "portals")
              << ", " << g.description.realWalls.size() << " real walls\n"
              << json.string() << "\n";
    return 0;
}

}  // namespace cavewall::tools
