// Wall baking on the generated plant (headless llvmpipe): the time per texture (render, MIP
// chain + tiled file) at several resolution caps, levels of detail against full detail on a
// sample of the walkthrough's textures (time, triangles, PSNR; file encoding at two zip
// levels), and a whole bake of the plant's plan.
//
// The plant has CAVEWALL_BENCH_TRIANGLES drawn triangles (default 2000000, the default plant;
// set it lower on slow machines). The whole bake uses the default plan (alpha 10°, 1017
// textures on the default plant) capped at CAVEWALL_BENCH_MAX_RES texels (default 256) into a
// fresh cache, with 2 writer threads. Run: build/bench/cavewall_bench_bake.
#include "display/gl/context.h"
#include "scenes/generate.h"
#include "metrics/image_compare.h"
#include "metrics/image_error.h"
#include "scenes/loader.h"
#include "walls/bake_key.h"
#include "walls/gl/baker.h"
#include "walls/texture_mips.h"
#include "walls/gl/wall_renderer.h"
#include "walls/visibility.h"
#include "walls/wall_setup.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
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

display::gl::Context& context() {
    static const std::unique_ptr<display::gl::Context> c = display::gl::createHeadlessContext();
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
    walls::gl::WallTextureRenderer renderer(scene, 0.35f);
    const int cap = static_cast<int>(state.range(0));
    double renderMs = 0, fileMs = 0, texels = 0;
    std::size_t i = 0;
    for (auto _ : state) {
        const walls::Texture& t = plan.textures[i++ % plan.textures.size()];
        const int side = plan.walls[t.wall].cells[0] == t.cell ? 0 : 1;
        const walls::WallContents c = walls::wallContents(scene, d, table, t.wall, side);
        const glm::ivec2 res = walls::bakeResolution(t.resolution, cap);
        const Clock::time_point a = Clock::now();
        const scenes::Image image =
            renderer.render(walls::quadSeenFrom(plan.walls[t.wall].quad, side), t.samplingPoint, res, c.baked);
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

// Levels of detail in the bake (BakeSettings::lodTexels) against full detail, interleaved on
// the same textures: a sample of CAVEWALL_BENCH_TEXTURES (default 48) textures spread evenly
// over the plan of the bake the walkthrough uses (alpha 10°, min-zone 1 m, 10 texels per degree,
// at most 512 texels), each rendered at full detail and at BakeSettings::lodTexels (or
// $CAVEWALL_BENCH_LOD_TEXELS) texels, timed (draw until the GL
// finished, and read back), and compared: PSNR of the pooled squared error over all sampled
// textures (R, G, B as stored; metrics/image_error.h), the worst texture's PSNR and the largest
// per-texel difference (levels 0-255, any channel). Also the file stage of each texture, MIP
// chain and tiled TIFF at zip (level 6, the default) and zip:1, timed and sized.
// CAVEWALL_BENCH_SCENE names a scene.json to use instead of the generated plant.
void BM_BakeLodAgainstFullDetail(benchmark::State& state) {
    context();
    const char* named = std::getenv("CAVEWALL_BENCH_SCENE");
    const std::filesystem::path path = named && *named ? std::filesystem::path(named) : plantScene();
    scenes::SceneDescription d;
    const scenes::Scene scene = scenes::loadSceneFile(path, &d);
    walls::PlanOptions options;
    options.alphaDeg = 10.0;
    options.minZoneSize = 1.0;
    options.pixelsPerDegree = 10.0;
    const walls::WallSetup setup =
        walls::prepareWalls(scene, d, walls::planOptionsFor(options, walls::WallKind::Flat, 512));
    const Clock::time_point built = Clock::now();
    walls::gl::WallTextureRenderer full(scene, 0.35f, 0.0);
    const Clock::time_point fullMade = Clock::now();
    const char* tolerance = std::getenv("CAVEWALL_BENCH_LOD_TEXELS");
    const double lodTexels =
        tolerance && *tolerance ? std::strtod(tolerance, nullptr) : walls::gl::BakeSettings{}.lodTexels;
    walls::gl::WallTextureRenderer lod(scene, 0.35f, lodTexels);
    const double lodBuildS = std::chrono::duration<double>(Clock::now() - fullMade).count() -
                             std::chrono::duration<double>(fullMade - built).count();
    const std::size_t count = std::min(envSize("CAVEWALL_BENCH_TEXTURES", 48), setup.plan.textures.size());
    double fullDraw = 0, fullRead = 0, lodDraw = 0, lodRead = 0, fullTris = 0, lodTris = 0, maxErr = 0;
    double mips = 0, zip6 = 0, zip1 = 0, bytes6 = 0, bytes1 = 0;
    int maxDelta = 0;
    double worstPsnr = INFINITY;
    metrics::SquaredError pooled;
    for (auto _ : state)
        for (std::size_t k = 0; k < count; ++k) {
            const walls::Texture& t = setup.plan.textures[k * setup.plan.textures.size() / count];
            const int side = setup.plan.walls[t.wall].cells[0] == t.cell ? 0 : 1;
            const display::ScreenQuad quad = walls::quadSeenFrom(setup.plan.walls[t.wall].quad, side);
            const std::vector<int>& objects = setup.contents.at({t.wall, side}).baked;
            const glm::ivec2 res = walls::bakeResolution(t.resolution, 512);
            const scenes::Image a = full.render(quad, t.samplingPoint, res, objects);
            fullDraw += full.lastTiming().drawMs;
            fullRead += full.lastTiming().readMs;
            fullTris += double(full.lastStats().triangles);
            const scenes::Image b = lod.render(quad, t.samplingPoint, res, objects);
            lodDraw += lod.lastTiming().drawMs;
            lodRead += lod.lastTiming().readMs;
            lodTris += double(lod.lastStats().triangles);
            maxErr = std::max(maxErr, lod.lastLod().maxErrorPx);
            const metrics::SquaredError e = metrics::squaredError(b, a);
            pooled += e;
            worstPsnr = std::min(worstPsnr, e.psnrDb());
            maxDelta = std::max(maxDelta, metrics::compareImages(b, a).maxDelta);
            const Clock::time_point m0 = Clock::now();
            const std::vector<scenes::Image> levels = walls::premultipliedMipChain(b);
            const Clock::time_point m1 = Clock::now();
            walls::writeMipFile(benchFolder() / "zip6.tx", levels, {64, "zip"});
            const Clock::time_point m2 = Clock::now();
            walls::writeMipFile(benchFolder() / "zip1.tx", levels, {64, "zip:1"});
            mips += ms(m1 - m0);
            zip6 += ms(m2 - m1);
            zip1 += ms(Clock::now() - m2);
            bytes6 += double(std::filesystem::file_size(benchFolder() / "zip6.tx"));
            bytes1 += double(std::filesystem::file_size(benchFolder() / "zip1.tx"));
        }
    const double n = double(state.iterations() * count);
    state.counters["textures"] = double(count);
    state.counters["full_draw_ms"] = fullDraw / n;
    state.counters["lod_draw_ms"] = lodDraw / n;
    state.counters["read_ms"] = (fullRead + lodRead) / (2 * n);
    state.counters["full_tris"] = fullTris / n;
    state.counters["lod_tris"] = lodTris / n;
    state.counters["lod_build_s"] = lodBuildS;
    state.counters["lod_texels"] = lodTexels;
    state.counters["lod_err_texels_max"] = maxErr;
    state.counters["psnr_pooled_db"] = pooled.psnrDb();
    state.counters["psnr_worst_db"] = worstPsnr;
    state.counters["max_delta"] = maxDelta;
    state.counters["mip_ms"] = mips / n;
    state.counters["zip6_ms"] = zip6 / n;
    state.counters["zip1_ms"] = zip1 / n;
    state.counters["zip6_kB"] = bytes6 / n / 1024.0;
    state.counters["zip1_kB"] = bytes1 / n / 1024.0;
}
BENCHMARK(BM_BakeLodAgainstFullDetail)->Unit(benchmark::kSecond)->Iterations(1);

// The whole plan into an empty cache, once; then the same bake again (cache hit, no work).
void BM_BakeWholePlant(benchmark::State& state) {
    walls::gl::BakeRequest request;
    request.scene = plantScene();
    request.cache = benchFolder() / "cache";
    request.settings.maxResolution = static_cast<int>(envSize("CAVEWALL_BENCH_MAX_RES", 256));
    request.settings.jobs = 2;
    request.context = &context();
    walls::gl::BakeResult result, again;
    for (auto _ : state) {
        std::filesystem::remove_all(request.cache);
        result = walls::gl::bakeScene(request);
        const Clock::time_point a = Clock::now();
        again = walls::gl::bakeScene(request);
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
