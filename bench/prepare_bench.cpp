// Start-up cost of the virtual walls: walls::prepareWalls (visibility, what each wall side
// shows, the plan) on scene folders given on the command line, with the options `cavewall run`
// and `bench` use by default (flat walls, alpha 10°). Prints, per scene and run, the wall-clock
// and process CPU seconds of prepareWalls (loading excluded) and the plan's size and two hashes
// (FNV-1a) that must not change when only speed does: of the plan as `cavewall plan --json`
// writes it, and of every side's WallContents (lists and depths, bit for bit). Two builds can
// be compared side by side:
//   build/bench/cavewall_bench_prepare [--runs N] SCENE_DIR...
#include "scenes/loader.h"
#include "walls/plan_io.h"
#include "walls/wall_setup.h"

#include <chrono>
#include <cstdio>
#include <cstdint>
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

struct Fnv {
    std::uint64_t h = 1469598103934665603ull;
    void bytes(const void* p, std::size_t n) {
        for (std::size_t i = 0; i < n; ++i) h = (h ^ static_cast<const unsigned char*>(p)[i]) * 1099511628211ull;
    }
    void number(double v) { bytes(&v, sizeof v); }
    void ints(const std::vector<int>& v) {
        const std::uint64_t n = v.size();
        bytes(&n, sizeof n);
        bytes(v.data(), v.size() * sizeof(int));
    }
};

std::uint64_t contentsHash(const cavewall::walls::WallSetup& s) {
    Fnv f;
    for (const auto& [key, c] : s.contents) {
        f.bytes(&key.first, sizeof key.first), f.bytes(&key.second, sizeof key.second);
        f.ints(c.baked), f.ints(c.intersecting), f.number(c.depthBehind), f.number(c.depthNear);
    }
    return f.h;
}

std::uint64_t planHash(const cavewall::walls::Plan& plan) {
    const std::string text = cavewall::walls::planToJson(plan).dump(1);
    Fnv f;
    f.bytes(text.data(), text.size());
    return f.h;
}

}  // namespace

int main(int argc, char** argv) {
    using namespace cavewall;
    int runs = 1;
    std::vector<std::string> scenes;
    for (int i = 1; i < argc; ++i) {
        const std::string a = argv[i];
        if (a == "--runs" && i + 1 < argc)
            runs = std::max(1, std::atoi(argv[++i]));
        else
            scenes.push_back(a);
    }
    if (scenes.empty()) {
        std::fprintf(stderr, "usage: cavewall_bench_prepare [--runs N] SCENE_DIR...\n");
        return 2;
    }
    try {
        std::printf("scene,objects,walls,run,wall_s,cpu_s,sides,beyond,textures,plan_hash,contents_hash\n");
        for (const std::string& path : scenes) {
            scenes::SceneDescription d;
            const scenes::Scene scene = scenes::loadSceneFile(path, &d);
            for (int r = 0; r < runs; ++r) {
                const auto start = std::chrono::steady_clock::now();
                const double cpu = cpuSeconds();
                const walls::WallSetup s =
                    walls::prepareWalls(scene, d, walls::planOptionsFor({}, walls::WallKind::Flat, 1024));
                const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
                const double cpuUsed = cpuSeconds() - cpu;
                std::printf("%s,%zu,%zu,%d,%.3f,%.3f,%zu,%zu,%zu,%016llx,%016llx\n", path.c_str(), scene.objects.size(),
                            d.walls.size(), r, wall, cpuUsed, s.plan.sides.size(), s.plan.beyond.size(),
                            s.plan.textures.size(), (unsigned long long)planHash(s.plan),
                            (unsigned long long)contentsHash(s));
                std::fflush(stdout);
            }
        }
    } catch (const std::exception& e) {
        std::fprintf(stderr, "cavewall_bench_prepare: %s\n", e.what());
        return 1;
    }
    return 0;
}
