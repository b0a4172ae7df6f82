// The cache's content check (walls/content_hash.h) against the page-in it guards, on real baked
// textures: every ".bct" file of $CAVEWALL_BENCH_TEXTURES (a bake folder, e.g. the plant's BC1
// bake; at most $CAVEWALL_BENCH_TEXTURE_COUNT files, default all), one thread, as the texture
// pager's loader thread does it (walls/texture_pager.h):
//  - page_in: per file, read it whole (the page cache is warm after the first pass), check its
//    content hash, decode its blocks (zstd; inflate in version 1 files) and find its covered
//    rectangle. Counters: read_ms, check_ms, decode_ms per texture and check_share_pct = check
//    / (read + check + decode) in per cent; file_kb, the mean file size.
//  - hash/<name>: the hashes the check could use over the same files' bytes, in memory:
//    xxh64 (contentHash), fnv1a (byte-wise FNV-1a 64, the bake keys' hash) and zlib's crc32;
//    bytes_per_second.
// Without the variable it reads nothing and says so. It prints figures, never a verdict.
// Example: CAVEWALL_BENCH_TEXTURES=~/.cache/cavewall/<bake key> build/bench/cavewall_bench_cache_check
#include "walls/bake_manifest.h"
#include "walls/content_hash.h"
#include "walls/texture_blocks.h"
#include "walls/texture_pager.h"

#include <benchmark/benchmark.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace cavewall;
using Clock = std::chrono::steady_clock;

const std::vector<std::filesystem::path>& files() {
    static const std::vector<std::filesystem::path> out = [] {
        std::vector<std::filesystem::path> found;
        const char* folder = std::getenv("CAVEWALL_BENCH_TEXTURES");
        if (!folder || !*folder) return found;
        for (const auto& e : std::filesystem::directory_iterator(folder))
            if (e.path().extension() == ".bct") found.push_back(e.path());
        std::sort(found.begin(), found.end());
        const char* count = std::getenv("CAVEWALL_BENCH_TEXTURE_COUNT");
        if (count && *count) found.resize(std::min<std::size_t>(found.size(), std::strtoul(count, nullptr, 10)));
        std::cerr << "cache check: " << found.size() << " .bct files in " << folder << "\n";
        return found;
    }();
    return out;
}

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

void pageIn(benchmark::State& state) {
    if (files().empty()) {
        state.SkipWithError("set CAVEWALL_BENCH_TEXTURES to a bake folder of .bct textures");
        return;
    }
    double read = 0.0, check = 0.0, decode = 0.0;
    std::size_t bytes = 0, pages = 0;
    for (auto _ : state)
        for (const std::filesystem::path& file : files()) {
            Clock::time_point t = Clock::now();
            const std::optional<std::string> got = walls::readFileBytes(file);
            read += secondsSince(t);
            t = Clock::now();
            benchmark::DoNotOptimize(walls::contentHash(*got));
            check += secondsSince(t);
            t = Clock::now();
            const walls::TextureLevels levels = walls::blocksFromBytes(*got, file.string());
            benchmark::DoNotOptimize(walls::coveredRect(levels, walls::kCoveredMargin));
            decode += secondsSince(t);
            bytes += got->size();
            ++pages;
        }
    const double n = double(pages);
    state.counters["read_ms"] = read * 1000.0 / n;
    state.counters["check_ms"] = check * 1000.0 / n;
    state.counters["decode_ms"] = decode * 1000.0 / n;
    state.counters["check_share_pct"] = 100.0 * check / (read + check + decode);
    state.counters["file_kb"] = double(bytes) / n / 1024.0;
    state.counters["textures"] = double(files().size());
}

// Every file's bytes, read once.
const std::vector<std::string>& contents() {
    static const std::vector<std::string> out = [] {
        std::vector<std::string> c;
        for (const std::filesystem::path& f : files()) c.push_back(walls::readFileBytes(f).value());
        return c;
    }();
    return out;
}

enum class Hash { Xxh64, Fnv1a, Crc32 };

void hash(benchmark::State& state, Hash which) {
    if (contents().empty()) {
        state.SkipWithError("set CAVEWALL_BENCH_TEXTURES to a bake folder of .bct textures");
        return;
    }
    std::size_t bytes = 0;
    for (auto _ : state)
        for (const std::string& c : contents()) {
            switch (which) {
                case Hash::Xxh64: benchmark::DoNotOptimize(walls::contentHash(c)); break;
                case Hash::Fnv1a: benchmark::DoNotOptimize(walls::fnv1a(c)); break;
                case Hash::Crc32:
                    benchmark::DoNotOptimize(crc32(crc32(0L, Z_NULL, 0), reinterpret_cast<const Bytef*>(c.data()),
                                                   static_cast<uInt>(c.size())));
                    break;
            }
            bytes += c.size();
        }
    state.SetBytesProcessed(static_cast<std::int64_t>(bytes));
}

}  // namespace

BENCHMARK(pageIn)->MinTime(2.0)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(hash, xxh64, Hash::Xxh64)->MinTime(1.0)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(hash, fnv1a, Hash::Fnv1a)->MinTime(1.0)->UseRealTime()->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(hash, crc32, Hash::Crc32)->MinTime(1.0)->UseRealTime()->Unit(benchmark::kMillisecond);

BENCHMARK_MAIN();
