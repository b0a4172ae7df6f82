#pragma once
// `cavewall draw-bench SCENE`: the draw path alone, timed on one fixed view, so that
// it can be set beside another viewer drawing the same mesh (tools/osg-compare.sh runs
// OpenSceneGraph's osgviewer on the same box hall).
//
// The view is osgviewer's home view of the scene's bounds (app/bench/draw_view.h): one square
// screen of `resolution` pixels, symmetric `fovDeg` vertical field of view, mono. The scene is
// drawn by SceneRenderer::render (the same path as `cavewall bench`'s full-geometry mode and
// every walls mode's near geometry), with its default back-face culling and with
// RenderSettings::cullBackFaces off (both faces of everything: osgviewer's work), frame by frame
// in turn (ABBA order) after `warmup` untimed frames of each, so that neither configuration
// gains from its place in the run. A frame is timed on the CPU clock from before the clear to after
// glFinish, so it holds every stage of the GPU's work (on llvmpipe: vertex shading, binning,
// rasterisation); its process CPU time (all threads) is recorded beside it. With
// compareLighting the four configurations (culling on/off, default lighting / per pixel only)
// are timed in turn, in forward and then reverse order.

#include "app/bench/draw_view.h"
#include "scenes/scene.h"

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::bench::gl {

struct DrawBenchOptions {
    int frames = 40;                                // timed frames per configuration, >= 1
    int warmup = 5;                                 // untimed frames before them, >= 0
    int resolution = 1024;                          // pixels per side of the square view
    double fovDeg = bench::kOsgViewerFovDeg;        // vertical (and horizontal) field of view
    std::optional<std::filesystem::path> imageDir;  // write culled.png and both.png there
    // Also time both configurations with every draw lit per pixel (vertex lighting off,
    // render/vertex_lighting.h), in the same rotation: what lighting per vertex gains.
    bool compareLighting = false;
};

struct DrawBenchRow {
    bool cullBackFaces = true;
    bool perPixelOnly = false;  // vertex lighting off
    bench::DrawTiming timing;
    std::size_t trianglesSubmitted = 0;  // per frame, after frustum culling
    std::vector<double> frameMs;         // every timed frame, in order (wall clock)
    std::vector<double> cpuMs;           // the same frames' process CPU time
};

struct DrawBenchResult {
    std::string glRenderer;  // GL_RENDERER
    bench::HomeView view;
    std::size_t triangles = 0;            // the scene's drawn triangles
    double vertexBytesPerTriangle = 0.0;  // GPU vertex buffer / triangles
    double indexBytesPerTriangle = 0.0;   // GPU index buffer / triangles
    std::vector<DrawBenchRow> rows;       // culling on, then off (each with the
                                          // default lighting, then per pixel only
                                          // with compareLighting)
};

// Runs both configurations in a headless context. `scene` must have at least one object.
// Throws cavewall::Error when no GL 4.5 context is available or an image cannot be written.
DrawBenchResult runDrawBench(const scenes::Scene& scene, const DrawBenchOptions& options);

}  // namespace cavewall::bench::gl
