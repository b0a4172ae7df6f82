// cavewall: head-tracked CAVE rendering of large indoor CAD models with textured virtual walls.
#include "config/error.h"
#include "tools/commands.h"

#include <cstring>
#include <exception>
#include <iostream>

#ifdef __GLIBC__
#include <malloc.h>
#endif

namespace cavewall::tools {
namespace {

const Command kCommands[] = {
#ifdef CAVEWALL_HAVE_GL
    {"view", "open a window on a model and look around with mouse and keys (F1: help)", kViewUsage, runView},
#endif
    {"display", "check a display configuration: screens, head, tracking (summary; --png: a picture)", kDisplayUsage,
     runDisplay},
    {"frustum", "print every screen's and eye's off-axis view and projection", kFrustumUsage, runFrustum},
    {"track", "read a head tracker and print calibrated, filtered, predicted head poses", kTrackUsage, runTrack},
    {"calibrate", "fit tracking.caveFromTracker to tracked points paired with known cave points", kCalibrateUsage,
     runCalibrate},
    {"bench", "measure error against run time; --stability: the numerical stability report", kBenchUsage, runBench},
    {"generate", "write a generated plant or house (.glb + scene.json) deterministically from a seed", kGenerateUsage,
     runGenerate},
    {"plan", "plan the zones and textures of every virtual wall (summary, JSON, PNG diagram)", kPlanUsage, runPlan},
    {"walls", "propose cells and virtual walls for a model nobody prepared (scene.json, diagram)", kWallsUsage,
     runWalls},
#ifdef CAVEWALL_HAVE_GL
    {"render", "render one frame of a scene to PNG files (one per screen and eye, plus a fold-out)", kRenderUsage,
     runRender},
    {"demo", "walk cave4 through the generated plant with and without virtual walls (report.md)", kDemoUsage, runDemo},
    {"run", "walk through a scene with textured virtual walls: frames.csv, walls.csv, images", kRunUsage, runRun},
    {"draw-bench", "time the draw path alone on osgviewer's home view (culling on and off)", kDrawBenchUsage,
     runDrawBench},
    {"bake", "bake the textures of every virtual wall into the cache (tiled MIP-mapped files + manifest)", kBakeUsage,
     runBake},
#endif
};

void printHelp() {
    std::cout << "usage: cavewall <command> [options]\n"
                 "       cavewall <command> --help\n"
                 "       cavewall --version\n\ncommands:\n";
    for (const Command& c : kCommands)
        std::cout << "  " << c.name << std::string(std::strlen(c.name) < 11 ? 11 - std::strlen(c.name) : 1, ' ')
                  << c.summary << "\n";
}

int dispatch(int argc, char** argv) {
    if (argc == 2 && (!std::strcmp(argv[1], "--version") || !std::strcmp(argv[1], "version"))) {
        std::cout << "cavewall " CAVEWALL_VERSION "\n";
        return 0;
    }
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

// Keeps freed heap memory in the process instead of handing it back to the kernel. Mesa's
// llvmpipe allocates and frees its vertex and bin buffers (megabytes) on every draw; with
// glibc's defaults the freed top of each heap is trimmed and the next frame faults every page
// back in, zeroed: a quarter of the process's time went to page faults in a profile of
// `draw-bench` on the 100 k-triangle box hall, and its CPU time per frame fell from 116 ms to
// 31 ms (culled) and from 230 to 47 ms (culling off) with trimming disabled, 1024 x 1024
// (docs/benchmarking.md). The cost: the resident size stays at its peak.
void keepFreedMemory() {
#ifdef __GLIBC__
    mallopt(M_TRIM_THRESHOLD, 1 << 30);   // trim only when over 1 GiB is free at a heap's top
    mallopt(M_MMAP_THRESHOLD, 32 << 20);  // blocks below 32 MiB come from the heap, reused
#endif
}

}  // namespace
}  // namespace cavewall::tools

int main(int argc, char** argv) {
    cavewall::tools::keepFreedMemory();
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
