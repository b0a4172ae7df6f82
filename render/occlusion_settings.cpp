#include "render/occlusion_settings.h"

namespace cavewall::render {

std::string describe(const OcclusionSettings& settings) {
    if (!settings.on) return "off";
    return "on, in views whose list submits at least " + std::to_string(settings.minTriangles) +
           " triangles in at least " + std::to_string(settings.minDraws) + " draws";
}

}  // namespace cavewall::render
