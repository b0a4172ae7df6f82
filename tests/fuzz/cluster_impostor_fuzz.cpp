// Fuzz target: a cluster's impostor files in the cache (hierarchy/cluster_cache.h), read as
// hierarchy/gl/cluster_impostors.cpp reads them: the bytes as cluster.json, and as an
// f<face>r<region>.tx MIP file whose levels are checked (read from memory by the reader's
// in-memory entry point, which shares every step after the open with the file's).
#include "config/error.h"
#include "hierarchy/cluster_cache.h"
#include "scenes/image_io.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>
#include <span>
#include <string_view>

namespace {

void record(std::string_view text) {
    using namespace cavewall::hierarchy;
    try {
        const ClusterRecord r = parseClusterRecord(text, "cluster.json");
        if (r.version != kClusterCacheVersion) return;
        // What is accepted is in range, lists every file, and reads back the same.
        if (r.files.size() != static_cast<std::size_t>(kBoxFaces * kFaceRegions)) __builtin_trap();
        for (const FaceAverage& a : r.faces)
            if (!(a.coverage >= 0.0f && a.coverage <= 1.0f)) __builtin_trap();
        if (parseClusterRecord(clusterRecordJson(r), "again.json") != r) __builtin_trap();
    } catch (const cavewall::Error&) {}
}

void mipFile(const std::uint8_t* data, std::size_t size) {
    try {
        const std::vector<cavewall::scenes::Image> levels =
            cavewall::scenes::readMipLevels(std::span(data, size), "f0r0.tx");
        // What is decoded is RGBA8, one texel per pixel; the chain check answers either way.
        for (const cavewall::scenes::Image& l : levels)
            if (l.rgba.size() != static_cast<std::size_t>(l.width) * static_cast<std::size_t>(l.height) * 4)
                __builtin_trap();
        if (!levels.empty())
            (void)cavewall::hierarchy::impostorLevelsProblem(levels, {levels[0].width, levels[0].height});
    } catch (const cavewall::Error&) {}
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    record(std::string_view(reinterpret_cast<const char*>(data), size));
    mipFile(data, size);
    return 0;
}
