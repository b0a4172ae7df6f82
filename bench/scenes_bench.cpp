// CPU frustum culling on the generated plant (2 M drawn triangles): BVH against brute force.
// Views: every walk-path point at eye height looking in four directions, 90° x 90° frustum,
// reversed-Z infinite far plane. Counters: objects and triangles kept per view, and the same
// with the cell filter keeping only the viewer's cell (objects without a cell always kept).
// Argument: the plant is tiled N x N (halls 100 m apart, meshes shared) to show how both
// methods scale with the object count; the views stay in the hall at the origin.
#include "scenes/bvh.h"
#include "scenes/cell_assignment.h"
#include "scenes/generate.h"
#include "scenes/region.h"

#include <benchmark/benchmark.h>

#include <glm/gtc/matrix_transform.hpp>

#include <map>

namespace {

using namespace cavewall::scenes;

struct Fixture {
    GeneratedScene plant = generatePlant({});
    Bvh bvh;
    std::vector<glm::dmat4> views;
    std::vector<int> viewCells;

    explicit Fixture(int tiles) {
        const std::vector<Object> hall = plant.scene.objects;
        plant.scene.objects.clear();
        for (int i = 0; i < tiles; ++i)
            for (int j = 0; j < tiles; ++j) {
                const glm::dmat4 shift =
                    glm::translate(glm::dmat4(1.0), glm::dvec3(100.0 * (i - tiles / 2), 0, 100.0 * (j - tiles / 2)));
                for (const Object& o : hall) addObject(plant.scene, o.mesh, shift * o.worldFromModel, o.name, o.role);
            }
        // Cell assignment as loadScene does it, so the cell filter has something to filter.
        assignCells(plant.scene, plant.description.cells);
        bvh = Bvh(plant.scene);
        glm::dmat4 projection(0.0);  // 90° fov, aspect 1, near 0.05, infinite far, reversed-Z
        projection[0][0] = projection[1][1] = 1.0;
        projection[2][3] = -1.0;
        projection[3][2] = 0.05;
        for (const glm::dvec3& eye : plant.description.walkPath)
            for (int dir = 0; dir < 4; ++dir) {
                const double a = glm::radians(90.0 * dir);
                views.push_back(projection *
                                glm::lookAt(eye, eye + glm::dvec3(std::sin(a), 0, -std::cos(a)), {0, 1, 0}));
                viewCells.push_back(findCell(plant.description.cells, eye));
            }
    }
};

const Fixture& fixture(int tiles) {
    static std::map<int, Fixture> cache;  // built once per size for all benchmarks
    return cache.try_emplace(tiles, tiles).first->second;
}

void report(benchmark::State& state, std::size_t objects, std::size_t triangles, std::size_t views) {
    const Scene& s = fixture(static_cast<int>(state.range(0))).plant.scene;
    state.counters["objects"] = static_cast<double>(s.objects.size());
    state.counters["triangles"] = static_cast<double>(s.triangleCount());
    state.counters["keptObjects"] = static_cast<double>(objects) / static_cast<double>(views);
    state.counters["keptTriangles"] = static_cast<double>(triangles) / static_cast<double>(views);
    state.counters["views/s"] =
        benchmark::Counter(static_cast<double>(state.iterations() * views), benchmark::Counter::kIsRate);
}

std::size_t trianglesOf(const Scene& s, const std::vector<int>& kept) {
    std::size_t n = 0;
    for (int o : kept) n += s.meshes[s.objects[o].mesh].triangleCount();
    return n;
}

void BM_CullBvh(benchmark::State& state) {
    const Fixture& f = fixture(static_cast<int>(state.range(0)));
    std::vector<int> kept;
    std::size_t objects = 0, triangles = 0;
    for (auto _ : state)
        for (const glm::dmat4& v : f.views) {
            f.bvh.cull(v, kept);
            benchmark::DoNotOptimize(kept.data());
        }
    for (const glm::dmat4& v : f.views) {
        f.bvh.cull(v, kept);
        objects += kept.size();
        triangles += trianglesOf(f.plant.scene, kept);
    }
    report(state, objects, triangles, f.views.size());
}

void BM_CullBruteForce(benchmark::State& state) {
    const Fixture& f = fixture(static_cast<int>(state.range(0)));
    std::vector<int> kept;
    std::size_t objects = 0, triangles = 0;
    auto cull = [&](const glm::dmat4& v) {
        kept.clear();
        const Frustum frustum(v);
        const auto& objs = f.plant.scene.objects;
        for (std::size_t i = 0; i < objs.size(); ++i)
            if (frustum.intersects(objs[i].worldBounds)) kept.push_back(static_cast<int>(i));
    };
    for (auto _ : state)
        for (const glm::dmat4& v : f.views) {
            cull(v);
            benchmark::DoNotOptimize(kept.data());
        }
    for (const glm::dmat4& v : f.views) {
        cull(v);
        objects += kept.size();
        triangles += trianglesOf(f.plant.scene, kept);
    }
    report(state, objects, triangles, f.views.size());
}

void BM_CullBvhViewerCellOnly(benchmark::State& state) {
    const Fixture& f = fixture(static_cast<int>(state.range(0)));
    std::vector<int> kept;
    std::size_t objects = 0, triangles = 0;
    std::vector<std::vector<bool>> masks;
    for (int c : f.viewCells) {
        masks.emplace_back(f.plant.description.cells.size(), false);
        if (c >= 0) masks.back()[c] = true;
    }
    for (auto _ : state)
        for (std::size_t i = 0; i < f.views.size(); ++i) {
            f.bvh.cull(f.views[i], kept, &masks[i]);
            benchmark::DoNotOptimize(kept.data());
        }
    for (std::size_t i = 0; i < f.views.size(); ++i) {
        f.bvh.cull(f.views[i], kept, &masks[i]);
        objects += kept.size();
        triangles += trianglesOf(f.plant.scene, kept);
    }
    report(state, objects, triangles, f.views.size());
}

}  // namespace

BENCHMARK(BM_CullBvh)->Arg(1)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CullBruteForce)->Arg(1)->Arg(8)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_CullBvhViewerCellOnly)->Arg(1)->Unit(benchmark::kMicrosecond);
BENCHMARK_MAIN();
