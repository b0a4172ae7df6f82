// Micro-benchmarks of the display core's hot paths: one off-axis frustum, and a whole cave4
// frame of frusta (4 screens) in mono and separate stereo.
#include "config/display_config.h"
#include "display/display.h"
#include "display/off_axis.h"

#include <benchmark/benchmark.h>

namespace {

using namespace cavewall;

void BM_OffAxisFrustum(benchmark::State& state) {
    const display::ScreenQuad front{{-1.5, 0, -1.5}, {1.5, 0, -1.5}, {-1.5, 3, -1.5}};
    glm::dvec3 eye{0.3, 1.6, 0.2};
    for (auto _ : state) {
        eye.x = -eye.x;  // keep the compiler from hoisting the call
        benchmark::DoNotOptimize(display::offAxisFrustum(front, eye, {0.05, 1000.0}));
    }
    state.SetItemsProcessed(state.iterations());
}
BENCHMARK(BM_OffAxisFrustum);

void BM_Cave4FrameViews(benchmark::State& state) {
    config::DisplayConfig c = config::loadDisplayConfig("cave4");
    if (state.range(0)) c.stereo = config::StereoMode::Separate;
    const display::Display d(c);
    display::HeadPose head = d.defaultHead();
    for (auto _ : state) {
        head.position.x = -head.position.x + 0.01;
        benchmark::DoNotOptimize(d.views(head));
    }
    state.SetLabel(state.range(0) ? "stereo, 8 views" : "mono, 4 views");
}
BENCHMARK(BM_Cave4FrameViews)->Arg(0)->Arg(1);

}  // namespace

BENCHMARK_MAIN();
