// The image metrics of scenes/ on one 1024 x 1024 screen, as the bench will run them per frame:
// FLIP (metrics/flip.h) at a CAVE wall's 9 and 17 pixels per degree and the paper's 67, SSIM
// (metrics/ssim.h), the squared error behind pooled PSNR (metrics/image_error.h) and one frame
// pair of popping (metrics/popping.h). The images are a seeded picture (gradients, stripes and
// noise) and a copy with its stripes moved and colours shifted, so that every filter has work.
// One thread; the time per call is the figure to read.
#include "metrics/flip.h"
#include "metrics/image_error.h"
#include "metrics/popping.h"
#include "metrics/ssim.h"

#include <benchmark/benchmark.h>

#include <random>

namespace {

using namespace cavewall::scenes;
using namespace cavewall::metrics;

constexpr int kSize = 1024;

Image picture(int shift, int red, unsigned seed) {
    Image image{"picture", kSize, kSize, std::vector<std::uint8_t>(std::size_t{kSize} * kSize * 4, 255)};
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> noise(-8, 8);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            std::uint8_t* p = &image.rgba[(std::size_t{kSize} * y + x) * 4];
            const int stripe = ((x + shift) / 16) % 2 ? 40 : 0;
            p[0] = static_cast<std::uint8_t>(std::clamp(40 + x / 8 + stripe + red + noise(rng), 0, 255));
            p[1] = static_cast<std::uint8_t>(std::clamp(60 + y / 8 + stripe + noise(rng), 0, 255));
            p[2] = static_cast<std::uint8_t>(std::clamp(200 - (x + y) / 16 + noise(rng), 0, 255));
        }
    return image;
}

const Image& reference() {
    static const Image image = picture(0, 0, 1);
    return image;
}
const Image& test() {
    static const Image image = picture(3, 10, 2);
    return image;
}

void BM_Flip(benchmark::State& state) {
    const FlipOptions options{static_cast<double>(state.range(0))};
    for (auto _ : state) benchmark::DoNotOptimize(flip(test(), reference(), options).mean);
}
BENCHMARK(BM_Flip)->Arg(9)->Arg(17)->Arg(67)->Unit(benchmark::kMillisecond);

void BM_Ssim(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(ssim(test(), reference()));
}
BENCHMARK(BM_Ssim)->Unit(benchmark::kMillisecond);

void BM_SquaredError(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(squaredError(test(), reference()).sum);
}
BENCHMARK(BM_SquaredError)->Unit(benchmark::kMillisecond);

void BM_PoppingPair(benchmark::State& state) {
    for (auto _ : state) benchmark::DoNotOptimize(framePairPopping(reference(), reference(), test(), reference()));
}
BENCHMARK(BM_PoppingPair)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
