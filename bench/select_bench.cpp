// Per-frame blend weights of textured virtual walls (walls/frame_select.h): the whole frame's
// selection (cell, every bounding wall's texture weights, geometry cells) and one side's
// weights at a floor point, as the walkthrough runtime calls them (select once per frame,
// blendAt 9 times per wall for the pager's look-ahead).
#include "walls/frame_select.h"
#include "walls/plan.h"
#include "walls/visibility.h"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace cavewall;

// Three 24 m x 20 m cells in a row along z, cut by two virtual walls at z = 0 and z = 20.
scenes::SceneDescription hall() {
    scenes::SceneDescription d;
    d.cells.push_back({"near", {{12, 0}, {12, 20}, {-12, 20}, {-12, 0}}, 0.0});
    d.cells.push_back({"middle", {{12, -20}, {12, 0}, {-12, 0}, {-12, -20}}, 0.0});
    d.cells.push_back({"far", {{12, 20}, {12, 40}, {-12, 40}, {-12, 20}}, 0.0});
    scenes::VirtualWall a, b;
    a.name = "a";
    a.lowerLeft = {-12, 0, 0};
    a.lowerRight = {12, 0, 0};
    a.upperLeft = {-12, 6, 0};
    a.cells = {0, 1};
    b.name = "b";
    b.lowerLeft = {12, 0, 20};
    b.lowerRight = {-12, 0, 20};
    b.upperLeft = {12, 6, 20};
    b.cells = {0, 2};
    d.walls = {a, b};
    return d;
}

std::vector<glm::dvec3> eyes(int n) {
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> x(-12, 12), y(1.2, 2.0), z(0.05, 19.95);
    std::vector<glm::dvec3> out;
    for (int i = 0; i < n; ++i) out.push_back({x(rng), y(rng), z(rng)});
    return out;
}

struct Fixture {
    scenes::SceneDescription description = hall();
    walls::Plan plan;
    walls::VisibilityTable table;
    explicit Fixture(double alphaDeg) {
        walls::PlanOptions options;
        options.alphaDeg = alphaDeg;
        plan = walls::planZones(description, options);
        table = walls::computeVisibility(description);
    }
};

void BM_FrameSelect(benchmark::State& state) {
    const Fixture f(static_cast<double>(state.range(0)));
    const walls::FrameSelector selector(f.plan, f.table, f.description);
    const auto points = eyes(1024);
    std::size_t i = 0;
    for (auto _ : state) benchmark::DoNotOptimize(selector.select(points[i++ & 1023]));
    state.counters["zones"] = static_cast<double>(f.plan.zones.size());
}
BENCHMARK(BM_FrameSelect)->Arg(5)->Arg(10)->Arg(20)->ArgName("alphaDeg");

void BM_BlendAt(benchmark::State& state) {
    const Fixture f(static_cast<double>(state.range(0)));
    const walls::FrameSelector selector(f.plan, f.table, f.description);
    const auto points = eyes(1024);
    std::size_t i = 0;
    for (auto _ : state) {
        const glm::dvec3 e = points[i++ & 1023];
        benchmark::DoNotOptimize(selector.blendAt(0, {e.x, e.z}));
    }
}
BENCHMARK(BM_BlendAt)->Arg(5)->Arg(10)->Arg(20)->ArgName("alphaDeg");

}  // namespace

BENCHMARK_MAIN();
