// cavewall: head-tracked CAVE rendering of large indoor CAD models with textured virtual walls.
#include "config/error.h"
#include "tools/commands.h"

#include <cstring>
#include <exception>
#include <iostream>

namespace cavewall::tools {
namespace {

const Command kCommands[] = {
    {"frustum", "print every screen's and eye's off-axis view and projection", kFrustumUsage, runFrustum},
    {"track", "read a head tracker and print calibrated, filtered, predicted head poses", kTrackUsage, runTrack},
    {"bench", "measure error against run time; --stability: the numerical stability report", kBenchUsage, runBench},
    {"generate", "write a generated plant or house (.glb + scene.json) deterministically from a seed", kGenerateUsage, runGenerate},
    {"plan", "plan the zones and textures of every virtual wall (summary, JSON, PNG diagram)", kPlanUsage, runPlan},
    {"walls", "propose cells and virtual walls for a model nobody prepared (scene.json, diagram)", kWallsUsage, runWalls},
#ifdef CAVEWALL_HAVE_GL
    {"render", "render one frame of a scene to PNG files (one per screen and eye, plus a fold-out)", kRenderUsage, runRender},
    {"demo", "walk cave4 through the generated plant with and without virtual walls (report.md)", kDemoUsage, runDemo},
    {"run", "walk through a scene with textured virtual walls: frames.csv, walls.csv, images", kRunUsage, runRun},
    {"draw-bench", "time the draw path alone on osgviewer's home view (culling on and off)", kDrawBenchUsage, runDrawBench},
    {"bake", "bake the textures of every virtual wall into the cache (tiled MIP-mapped files + manifest)", kBakeUsage, runBake},
#endif
};

void printHelp() {
    std::cout << "usage: cavewall <command> [options]\n"
                 "       cavewall <command> --help\n\ncommands:\n";
    for (const Command& c : kCommands) std::cout << "  " << c.name << std::string(std::strlen(c.name) < 11 ? 11 - std::strlen(c.name) : 1, ' ') << c.summary << "\n";
}

int dispatch(int argc, char** argv) {
    if (argc < 2 || !std::strcmp(argv[1], "--help") || !std::strcmp(argv[1], "-h") || !std::strcmp(argv[1], "help")) {
        printHelp();
        return argc < 2 ? 2 : 0;
    }
    for (const Command& c : kCommands) {
        if (std::strcmp(argv[1], c.name) != 0) continue;
        std::vector<std::string> args(argv + 2, argv + argc);
        for (const auto& a : args)
            if (a == "--help" || a == "-h") {
                std::cout << c.usage;
                return 0;
            }
        return c.run(args);
    }
    std::cerr << "cavewall: unknown command '" << argv[1] << "' (see cavewall --help)\n";
    return 2;
}

}  // namespace
}  // namespace cavewall::tools

int main(int argc, char** argv) {
    try {
        return cavewall::tools::dispatch(argc, argv);
    } catch (const cavewall::Error& e) {
        std::cerr << "cavewall: error: " << e.what() << "\n";
        return 1;
    } catch (const std::exception& e) {
        std::cerr << "cavewall: internal error: " << e.what() << "\n";
        return 3;
    }
}
