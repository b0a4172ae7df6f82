// Fuzz target: a projector warp file (display/warp_mesh.h), dispatched as loadWarpMesh does:
// MPCDI PFM when the bytes start with "PF", else the text format. What is accepted must be
// consistent: width * height nodes, every coordinate finite and in its range, triangles indexing
// only valid nodes, and the text writer's output must read back as the same mesh.
#include "config/error.h"
#include "display/screen_correction.h"
#include "display/warp_mesh.h"
#include "tests/fuzz/fuzz_target.h"

#include <cmath>
#include <string_view>

namespace {

bool inRange(glm::vec2 v, float low, float high) { return v.x >= low && v.x <= high && v.y >= low && v.y <= high; }

void check(const cavewall::display::WarpMesh& m) {
    using namespace cavewall::display;
    if (m.width < 2 || m.height < 2 || m.width > kMaxWarpNodesPerSide || m.height > kMaxWarpNodesPerSide)
        __builtin_trap();
    if (m.nodes.size() != static_cast<std::size_t>(m.width) * static_cast<std::size_t>(m.height)) __builtin_trap();
    for (const WarpNode& n : m.nodes) {
        if (!inRange(n.xy, kMinWarpOutput, kMaxWarpOutput)) __builtin_trap();
        if (n.valid ? !inRange(n.uv, 0.0f, 1.0f) : n.uv != glm::vec2(0.0f)) __builtin_trap();
    }
    const std::vector<unsigned> triangles = warpTriangles(m);
    if (triangles.size() % 3 != 0) __builtin_trap();
    for (unsigned index : triangles)
        if (index >= m.nodes.size() || !m.nodes[index].valid) __builtin_trap();
    if (!(parseWarpText(warpText(m), "written") == m)) __builtin_trap();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view bytes(reinterpret_cast<const char*>(data), size);
    try {
        using namespace cavewall::display;
        check(bytes.substr(0, 2) == "PF" ? parseWarpPfm(bytes, "fuzz.pfm") : parseWarpText(bytes, "fuzz.warp"));
    } catch (const cavewall::Error&) {}
    return 0;
}
