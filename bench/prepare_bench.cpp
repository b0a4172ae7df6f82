// Start-up cost of the virtual walls (issue 15): walls::prepareWalls (visibility, what each
// wall side shows, the plan) on scene folders given on the command line, with the options
// `cavewall run` and `bench` use by default (flat walls, alpha 10°). Prints, per scene and
// run, the wall-clock and process CPU seconds of prepareWalls (loading excluded) and the
// plan's size, so two builds can be compared side by side:
//   build/bench/cavewall_bench_prepare [--runs N] SCENE_DIR...
#include "scenes/loader.h"
#include "walls/wall_setup.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <string>
#include <vector>

namespace {

double cpuSeconds() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

}  // namespace

int main(int argc, char** argv) {
    using namespace cavewall;
    int runs = 1;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc) runs = std::max(1, std::atoi(argv[++i]));
        else scenes.push_back(a);
    }
    if (scenes.empty()) {
        std::fprintf(stderr, "usage: cavewall_bench_prepare [--runs N] SCENE_DIR...\n");
        return 2;
    }
    try {
        std::printf("scene,objects,walls,run,wall_s,cpu_s,sides,beyond,textures\n");
        for (const std::string& path : scenes) {
            scenes::SceneDescription d;
            const scenes::Scene scene = scenes::loadSceneFile(path, &d);
            for (int r = 0; r < runs; ++r) {
                const auto start = std::chrono::steady_clock::now();
                const double cpu = cpuSeconds();
                const walls::WallSetup s = walls::prepareWalls(scene, d, walls::planOptionsFor({}, walls::WallKind::Flat, 1024));
                const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                std::printf("%s,%zu,%zu,%d,%.3f,%.3f,%zu,%zu,%zu\n", path.c_str(), scene.objects.size(), d.walls.size(), r, wall,
                            cpuSeconds() - cpu, s.plan.sides.size(), s.plan.beyond.size(), s.plan.textures.size());
                std::fflush(stdout);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cavewall_bench_prepare: %s\n", e.what());
        return 1;
    }
    return 0;
}
