#include "app/bench/scale_plant.h"

#include "app/bench/scale.h"
#include "scenes/generate.h"
#include "walkthrough/frame_planner.h"

#include <chrono>

namespace cavewall::bench {

// The plant for `triangles`, generated into `folder` (and stamped, bench::kPlantStamp) unless
// it is there already.
std::filesystem::path plantFor(std::size_t triangles, const std::filesystem::path& folder, double& generateSeconds) {
    const std::filesystem::path sceneFile = folder / "scene.json";
    generateSeconds = 0.0;
    if (std::filesystem::exists(sceneFile)) return sceneFile;
    const auto start = std::chrono::steady_clock::now();
    scenes::GenerateOptions g;
    g.triangles = triangles;
    scenes::GeneratedScene generated = scenes::generatePlant(g);
    scenes::writeGenerated(generated, folder);
    bench::writePlantStamp(folder, triangles, generated.scene.triangleCount());
    generateSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return sceneFile;
}

// The drawn triangles of the plant generated for `triangles`, made again in memory (for a
// folder without a stamp).
std::size_t plantTriangles(std::size_t triangles) {
    scenes::GenerateOptions g;
    g.triangles = triangles;
    return scenes::generatePlant(g).scene.triangleCount();
}

// The textures the path's frames request (now or soon) with every texture resident, in id order.
std::set<int> requestedTextures(const scenes::Scene& scene, const scenes::SceneDescription& d,
                                const display::Display& display, const walls::WallSetup& setup,
                                const bench::EyePath& path) {
    walkthrough::FramePlanner planner(scene, d, display, &setup, walkthrough::Transition::Blend, 0.5);
    planner.requestCells(true);
    std::set<int> ids;
    for (const walkthrough::FrameInput& in : path.frames) {
        const walkthrough::TextureRequests r = planner.requests(in, display.views(in.head));
        ids.insert(r.now.begin(), r.now.end());
        ids.insert(r.soon.begin(), r.soon.end());
        planner.plan([](int) { return true; });
    }
    return ids;
}

}  // namespace cavewall::bench
