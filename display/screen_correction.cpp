#include "display/screen_correction.h"

namespace cavewall::display {

std::optional<ScreenCorrection> loadScreenCorrection(const config::DisplayConfig& config, int screen) {
    const config::Screen& s = config.screens.at(screen);
    if (!s.corrected()) return std::nullopt;
    ScreenCorrection c;
    if (!s.warp.empty()) c.warp = loadWarpMesh(config::screenFilePath(config, s.warp));
    if (!s.blend.empty()) c.blend = loadBlendMask(config::screenFilePath(config, s.blend));
    c.blackLevel = glm::vec3(s.blackLevel);
    return c;
}

std::vector<unsigned> warpTriangles(const WarpMesh& mesh) {
    std::vector<unsigned> out;
    const auto index = [&](int i, int j) { return static_cast<unsigned>(j * mesh.width + i); };
    for (int j = 0; j + 1 < mesh.height; ++j)
        for (int i = 0; i + 1 < mesh.width; ++i) {
            const unsigned a = index(i, j), b = index(i + 1, j), c = index(i + 1, j + 1), d = index(i, j + 1);
            if (!(mesh.nodes[a].valid && mesh.nodes[b].valid && mesh.nodes[c].valid && mesh.nodes[d].valid)) continue;
            out.insert(out.end(), {a, b, c, a, c, d});
        }
    return out;
}

}  // namespace cavewall::display
