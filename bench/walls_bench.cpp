// Virtual-wall planning costs on the runtime path: zone lookup per frame (linear and indexed), the exact per-eye
// error bound (maxAngularError, called per frame for the actual eye), the planner's one-search
// decision, and planning a whole cell.
#include "walls/angular_error.h"
#include "walls/plan.h"
#include "walls/zone_index.h"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace cavewall;

// A 24 m x 40 m hall cut by one 24 m x 6 m virtual wall at z = 0.
scenes::SceneDescription hall() {
    scenes::SceneDescription d;
    d.cells.push_back({"front", {{12, 0}, {12, 20}, {-12, 20}, {-12, 0}}, 0.0});
    d.cells.push_back({"back", {{12, -20}, {12, 0}, {-12, 0}, {-12, -20}}, 0.0});
    scenes::VirtualWall w;
    w.name = "middle";
    w.lowerLeft = {-12, 0, 0};
    w.lowerRight = {12, 0, 0};
    w.upperLeft = {-12, 6, 0};
    w.cells = {0, 1};
    d.walls.push_back(w);
    return d;
}

const display::ScreenQuad kWall{{-12, 0, 0}, {12, 0, 0}, {-12, 6, 0}};

std::vector<glm::dvec3> eyes(int n) {
    std::mt19937 rng(1);
    std::uniform_real_distribution<double> x(-12, 12), y(1.2, 2.0), z(2, 20);
    std::vector<glm::dvec3> out;
    for (int i = 0; i < n; ++i) out.push_back({x(rng), y(rng), z(rng)});
    return out;
}

void BM_ZoneLookup(benchmark::State& state) {
    const walls::Plan plan = walls::planZones(hall());
    const auto points = eyes(1024);
    std::size_t i = 0;
    for (auto _ : state) {
        const glm::dvec3 e = points[i++ & 1023];
        benchmark::DoNotOptimize(walls::findZone(plan, 0, 0, {e.x, e.z}));
    }
    state.counters["zones"] = double(plan.sides[0].zoneCount);
}
BENCHMARK(BM_ZoneLookup);

void BM_ZoneIndexLookup(benchmark::State& state) {
    const walls::Plan plan = walls::planZones(hall());
    const walls::ZoneIndex index(plan);
    const auto points = eyes(1024);
    std::size_t i = 0;
    for (auto _ : state) {
        const glm::dvec3 e = points[i++ & 1023];
        benchmark::DoNotOptimize(index.find(0, 0, {e.x, e.z}));
    }
}
BENCHMARK(BM_ZoneIndexLookup);

void BM_MaxAngularError(benchmark::State& state) {
    const auto points = eyes(1024);
    const double depth = state.range(0) ? 20.0 : walls::kInfiniteDepth;
    std::size_t i = 0;
    for (auto _ : state) {
        const glm::dvec3 e = points[i++ & 1023];
        benchmark::DoNotOptimize(walls::maxAngularError(e, {e.x + 0.7, 1.6, e.z + 0.4}, kWall, depth));
    }
}
BENCHMARK(BM_MaxAngularError)->Arg(0)->Arg(1)->ArgName("finiteDepth");

void BM_ErrorWithin(benchmark::State& state) {
    const auto points = eyes(1024);
    std::size_t i = 0;
    for (auto _ : state) {
        const glm::dvec3 e = points[i++ & 1023];
        benchmark::DoNotOptimize(
            walls::errorWithin(e, {e.x + 0.7, 1.6, e.z + 0.4}, kWall, walls::kInfiniteDepth, glm::radians(10.0)));
    }
}
BENCHMARK(BM_ErrorWithin);

void BM_PlanHall(benchmark::State& state) {
    const auto d = hall();
    std::size_t textures = 0;
    for (auto _ : state) textures = walls::planZones(d).textures.size();
    state.counters["textures"] = double(textures);
}
BENCHMARK(BM_PlanHall)->Unit(benchmark::kMillisecond);

// Planning time against the hall's size (hostile input must not make the planner spin). A
// W x W hall (W = the argument, metres) cut across by one 8 m high virtual wall W wide; 2000
// is a 2 km x 2 km hall, 2000 x 1000 cells.
void BM_PlanLargeHall(benchmark::State& state) {
    const double w = double(state.range(0)), half = 0.5 * w;
    scenes::SceneDescription d;
    d.cells.push_back({"front", {{half, 0}, {half, half}, {-half, half}, {-half, 0}}, 0.0});
    d.cells.push_back({"back", {{half, -half}, {half, 0}, {-half, 0}, {-half, -half}}, 0.0});
    scenes::VirtualWall wall;
    wall.name = "middle";
    wall.lowerLeft = {-half, 0, 0};
    wall.lowerRight = {half, 0, 0};
    wall.upperLeft = {-half, 8, 0};
    wall.cells = {0, 1};
    d.walls.push_back(wall);
    std::size_t textures = 0;
    for (auto _ : state) textures = walls::planZones(d).textures.size();
    state.counters["textures"] = double(textures);
}
BENCHMARK(BM_PlanLargeHall)
    ->Arg(48)
    ->Arg(192)
    ->Arg(1000)
    ->Arg(2000)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
