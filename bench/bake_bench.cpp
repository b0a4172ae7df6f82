// Wall baking on the generated plant (headless llvmpipe): the time per texture (render, MIP
// chain + tiled file) at several resolution caps, and a whole bake of the plant's plan.
//
// The plant has CAVEWALL_BENCH_TRIANGLES drawn triangles (default 2000000, the default plant;
// set it lower on slow machines). The whole bake uses the default plan (alpha 10°, 1017
// textures on the default plant) capped at CAVEWALL_BENCH_MAX_RES texels (default 256) into a
// fresh cache, with 2 writer threads. Run: build/bench/cavewall_bench_bake.
#include "display/gl/context.h"
#include "scenes/generate.h"
#include "scenes/loader.h"
#include "walls/bake_key.h"
#include "walls/gl/baker.h"
#include "walls/texture_mips.h"
#include "walls/gl/wall_renderer.h"
#include "walls/visibility.h"

#include <benchmark/benchmark.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>

namespace {

using namespace cavewall;
using Clock = std::chrono::steady_clock;

std::size_t envSize(const char* name, std::size_t fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

std::filesystem::path benchFolder() { return std::filesystem::temp_directory_path() / "cavewall-bench-bake"; }

// The plant's scene.json, generated once per process.
const std::filesystem::path& plantScene() {
    static const std::filesystem::path path = [] {
        scenes::GenerateOptions o;
        o.triangles = envSize("CAVEWALL_BENCH_TRIANGLES", 2000000);
        scenes::GeneratedScene g = scenes::generatePlant(o);
        return scenes::writeGenerated(g, benchFolder() / ("plant-" + std::to_string(o.triangles)));
    }();
    return path;
}

gl::Context& context() {
    static const std::unique_ptr<gl::Context> c = gl::createHeadlessContext();
    c->makeCurrent();
    return *c;
}

double ms(Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); }

// One texture after another (cycling through the plan): render, then MIP chain and file.
void BM_BakeTexture(benchmark::State& state) {
    context();
    scenes::SceneDescription d;
    const scenes::Scene scene = scenes::loadSceneFile(plantScene(), &d);
    const walls::Plan plan = walls::planZones(d);
    const walls::VisibilityTable table = walls::computeVisibility(d);
    gl::WallTextureRenderer renderer(scene, 0.35f);
    const int cap = static_cast<int>(state.range(0));
    double renderMs = 0, fileMs = 0, texels = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        const walls::Texture& t = plan.textures[i++ % plan.textures.size()];
        const int side = plan.walls[t.wall].cells[0] == t.cell ? 0 : 1;
        const walls::WallContents c = walls::wallContents(scene, d, table, t.wall, side);
        const glm::ivec2 res = gl::bakeResolution(t.resolution, cap);
        const Clock::time_point a = Clock::now();
        const scenes::Image image = renderer.render(walls::quadSeenFrom(plan.walls[t.wall].quad, side), t.samplingPoint, res, c.baked);
        const Clock::time_point b = Clock::now();
        walls::writeMipFile(benchFolder() / "one.tx", walls::premultipliedMipChain(image));
        renderMs += ms(b - a);
        fileMs += ms(Clock::now() - b);
        texels += double(res.x) * res.y;
    }
    const double n = double(state.iterations());
    state.counters["render_ms"] = renderMs / n;
    state.counters["mip_file_ms"] = fileMs / n;
    state.counters["texels"] = texels / n;
    state.counters["scene_tris"] = double(scene.triangleCount());
}
BENCHMARK(BM_BakeTexture)->Arg(256)->Arg(1024)->Unit(benchmark::kMillisecond)->Iterations(20);

// The whole plan into an empty cache, once; then the same bake again (cache hit, no work).
void BM_BakeWholePlant(benchmark::State& state) {
    gl::BakeRequest request;
    request.scene = plantScene();
    request.cache = benchFolder() / "cache";
    request.settings.maxResolution = static_cast<int>(envSize("CAVEWALL_BENCH_MAX_RES", 256));
    request.settings.jobs = 2;
    request.context = &context();
    gl::BakeResult result, again;
    for (auto _ : state) {
        std::filesystem::remove_all(request.cache);
        result = gl::bakeScene(request);
        const Clock::time_point a = Clock::now();
        again = gl::bakeScene(request);
        state.counters["rebake_unchanged_s"] = std::chrono::duration<double>(Clock::now() - a).count();
    }
    state.counters["textures"] = double(result.baked);
    state.counters["bake_s"] = result.seconds;
    state.counters["ms_per_texture"] = 1000.0 * result.seconds / std::max(1, result.baked);
    state.counters["MB"] = double(result.totalBytes) / (1024.0 * 1024.0);
    state.counters["rebaked"] = double(again.baked);
    state.counters["max_res"] = request.settings.maxResolution;
}
BENCHMARK(BM_BakeWholePlant)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
