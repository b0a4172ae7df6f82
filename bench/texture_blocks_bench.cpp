// S3TC encoding of baked wall textures (walls/texture_blocks.h) on real bakes: a sample of a bake
// folder's RGBA8 textures (every k-th ".tx" file of $CAVEWALL_BENCH_TEXTURES, at most
// $CAVEWALL_BENCH_TEXTURE_COUNT of them, default 48), each file's whole MIP chain encoded as BC1
// and as BC3 and written as a ".bct" file, one thread. Without the variable it reads nothing and
// says so. Counters, over the sample:
//  - ms_per_texture: encoding (libsquish cluster fit) plus deflate and the atomic write;
//  - disk_ratio: ".bct" bytes / ".tx" bytes (the TIFF files as baked); gpu_ratio: block bytes /
//    RGBA8 bytes (1/8 for BC1, 1/4 for BC3 but for the 1 x 1 and 2 x 2 levels' whole blocks);
//  - psnr_over_grey_db: pooled PSNR of level 0 drawn over an opaque linear grey 0.18 (what the
//    wall pass shows: premultiplied colour + (1 - alpha) grey, sRGB-encoded), decoded blocks
//    against the RGBA8 texels; R, G, B of every texel.
// Example: CAVEWALL_BENCH_TEXTURES=~/.cache/cavewall/<bake key> build/bench/cavewall_bench_texture_blocks
#include "metrics/image_error.h"
#include "scenes/image_io.h"
#include "walls/texture_blocks.h"
#include "walls/texture_mips.h"

#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <unistd.h>
#include <vector>

namespace {

using namespace cavewall;

struct Sample {
    std::vector<std::vector<scenes::Image>> textures;  // every MIP level of each sampled file
    std::uintmax_t tiffBytes = 0;
};

const Sample& sample() {
    static const Sample s = [] {
        Sample out;
        const char* folder = std::getenv("CAVEWALL_BENCH_TEXTURES");
        if (!folder || !*folder) return out;
        const char* count = std::getenv("CAVEWALL_BENCH_TEXTURE_COUNT");
        const std::size_t wanted = count && *count ? std::strtoul(count, nullptr, 10) : 48;
        std::vector<std::filesystem::path> files;
        for (const auto& e : std::filesystem::directory_iterator(folder))
            if (e.path().extension() == ".tx") files.push_back(e.path());
        std::sort(files.begin(), files.end());
        const std::size_t step = std::max<std::size_t>(1, files.size() / std::max<std::size_t>(1, wanted));
        for (std::size_t i = 0; i < files.size() && out.textures.size() < wanted; i += step) {
            out.textures.push_back(scenes::readMipLevels(files[i]));
            out.tiffBytes += std::filesystem::file_size(files[i]);
        }
        std::cerr << "texture sample: " << out.textures.size() << " of " << files.size() << " files in " << folder
                  << "\n";
        return out;
    }();
    return s;
}

scenes::Image overGrey(const scenes::Image& premultiplied) {
    scenes::Image out = premultiplied;
    for (std::size_t i = 0; i < out.rgba.size(); i += 4) {
        const float a = premultiplied.rgba[i + 3] / 255.0f;
        for (int c = 0; c < 3; ++c)
            out.rgba[i + c] =
                walls::encodeSrgbByte(walls::srgbToLinear(premultiplied.rgba[i + c] / 255.0f) + (1.0f - a) * 0.18f);
        out.rgba[i + 3] = 255;
    }
    return out;
}

void encode(benchmark::State& state, walls::TextureFormat format) {
    const Sample& s = sample();
    if (s.textures.empty()) {
        state.SkipWithError("set CAVEWALL_BENCH_TEXTURES to a bake folder of RGBA8 (.tx) textures");
        return;
    }
    const std::filesystem::path folder =
        std::filesystem::temp_directory_path() / ("cavewall-bench-blocks-" + std::to_string(::getpid()));
    std::uintmax_t diskBytes = 0, gpuBytes = 0, rgbaBytes = 0;
    metrics::SquaredError error;
    double seconds = 0.0;
    for (auto _ : state) {
        diskBytes = gpuBytes = rgbaBytes = 0;
        error = {};
        for (std::size_t i = 0; i < s.textures.size(); ++i) {
            const auto start = std::chrono::steady_clock::now();
            const walls::TextureLevels blocks = walls::encodeLevels(s.textures[i], format);
            const std::filesystem::path file = folder / ("t" + std::to_string(i) + ".bct");
            walls::writeBlockFile(file, blocks);
            seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            state.PauseTiming();
            diskBytes += std::filesystem::file_size(file);
            gpuBytes += blocks.bytes();
            rgbaBytes += walls::TextureLevels(s.textures[i]).bytes();
            error += metrics::squaredError(overGrey(walls::decodeLevel(blocks.blocks[0], format)),
                                           overGrey(s.textures[i][0]));
            state.ResumeTiming();
        }
    }
    std::filesystem::remove_all(folder);
    const double n = double(state.iterations()) * double(s.textures.size());
    state.counters["ms_per_texture"] = seconds * 1000.0 / n;
    state.counters["disk_ratio"] = double(diskBytes) / double(s.tiffBytes);
    state.counters["gpu_ratio"] = double(gpuBytes) / double(rgbaBytes);
    state.counters["psnr_over_grey_db"] = error.psnrDb();
    state.counters["textures"] = double(s.textures.size());
}

}  // namespace

BENCHMARK_CAPTURE(encode, bc1, walls::TextureFormat::Bc1)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(encode, bc3, walls::TextureFormat::Bc3)->Iterations(1)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
