#include "render/occlusion_settings.h"

#include "config/json_reader.h"

namespace cavewall::render {

std::string describe(const OcclusionSettings& settings) {
    if (!settings.on) return "off";
    std::string text = "on, in views whose list submits at least " + std::to_string(settings.minTriangles) +
                       " triangles in at least " + std::to_string(settings.minDraws) + " draws";
    if (settings.minSavedShare > 0.0)
        text += ", paused for " + std::to_string(kOcclusionPausedFrames) + " frames in a view where it saved under " +
                config::formatNumber(100.0 * settings.minSavedShare) + " % of them";
    return text;
}

}  // namespace cavewall::render
