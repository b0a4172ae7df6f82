#pragma once
// The generated plant and its views, shared by the GL benches that render it (draw_bench.cpp,
// projector_pass_bench.cpp).
//
// Scene: $CAVEWALL_BENCH_SCENE, else <build>/bench/plant/scene.json, written on first use as
// `cavewall generate plant --out <build>/bench/plant` would (same generator, same bytes).
// Views: the walk-path points at eye height looking along -Z, +X, +Z and -X; the screen is a
// 2 m x 2 m square 1 m in front of the eye (90° x 90°), with an infinite far plane.
#include "display/off_axis.h"
#include "scenes/generate.h"

#include <glm/glm.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <vector>

namespace cavewall::bench {

inline std::filesystem::path plantScenePath() {
    if (const char* given = std::getenv("CAVEWALL_BENCH_SCENE")) return given;
    const std::filesystem::path folder = std::filesystem::path(CAVEWALL_BINARY_DIR) / "bench" / "plant";
    if (!std::filesystem::exists(folder / "scene.json")) {
        std::cerr << "generating the plant into " << folder.string() << " ...\n";
        scenes::GeneratedScene plant = scenes::generatePlant({});
        scenes::writeGenerated(plant, folder);
    }
    return folder / "scene.json";
}

inline std::vector<display::OffAxisFrustum> plantViews(const std::vector<glm::dvec3>& walkPath) {
    std::vector<display::OffAxisFrustum> views;
    const glm::dvec3 up(0, 1, 0);
    for (const glm::dvec3& eye : walkPath)
        for (const glm::dvec3& forward :
             {glm::dvec3(0, 0, -1), glm::dvec3(1, 0, 0), glm::dvec3(0, 0, 1), glm::dvec3(-1, 0, 0)}) {
            const glm::dvec3 right = glm::cross(forward, up), centre = eye + forward;
            const display::ScreenQuad quad{centre - right - up, centre + right - up, centre - right + up};
            views.push_back(display::offAxisFrustum(quad, eye, {0.05, INFINITY}));
        }
    return views;
}

}  // namespace cavewall::bench
