#include "app/bench/gl/draw_bench.h"
#include "config/error.h"
#include "config/json_reader.h"
#include "scenes/file_write.h"
#include "scenes/loader.h"
#include "tools/args.h"
#include "tools/commands.h"

#include <iostream>
#include <sstream>

namespace cavewall::tools {

const char* const kDrawBenchUsage =
    "usage: cavewall draw-bench SCENE [--frames N] [--warmup N] [--resolution N] [--fov DEG]\n"
    "                           [--csv FILE] [--images DIR] [--compare-lighting]\n"
    "\n"
    "Times the draw path alone on one fixed view of SCENE (glTF/GLB, scene.json or its folder),\n"
    "headless: the view OpenSceneGraph's osgviewer opens the same model with (its home position\n"
    "for the bounding sphere of the model's bounding box, 29.148 degrees vertical field of view,\n"
    "square), so the figures compare with osgviewer's on the same mesh (tools/osg-compare.sh,\n"
    "with `cavewall generate boxes`). The scene is drawn with back-face culling (cavewall's\n"
    "default) and without (both faces of everything, as osgviewer draws), each for --warmup\n"
    "untimed frames (default 5) and then --frames timed ones (default 40) at --resolution pixels\n"
    "per side (default 1024). A frame is timed from the clear to after glFinish. Prints per\n"
    "configuration the median and 90th-percentile frame milliseconds (wall clock), the median\n"
    "process CPU milliseconds per frame (all threads, llvmpipe's included: steady when other\n"
    "processes share the cores), million triangles and million pixels per second (at the\n"
    "median), and the GPU vertex and index bytes per triangle. --csv writes the rows (columns\n"
    "culling, lighting, triangles, median_ms, p90_ms, cpu_median_ms, mtriangles_per_s,\n"
    "mpixels_per_s, vertex_bytes_per_triangle, index_bytes_per_triangle); --images writes\n"
    "DIR/culled.png and DIR/both.png (the last frame of each). --compare-lighting adds both\n"
    "configurations with every draw lit per pixel (lighting 'per-pixel'; the default lights per\n"
    "vertex the draws whose difference is proven below 1/512 of the light), timed in the same\n"
    "rotation, and their images DIR/culled-per-pixel.png and DIR/both-per-pixel.png.\n";

namespace {

std::string csvText(const bench::gl::DrawBenchResult& r) {
    std::string csv =
        "culling,lighting,triangles,median_ms,p90_ms,cpu_median_ms,mtriangles_per_s,mpixels_per_s,vertex_bytes_per_"
        "triangle,"
        "index_bytes_per_triangle\n";
    for (const bench::gl::DrawBenchRow& row : r.rows)
        csv += std::string(row.cullBackFaces ? "on" : "off") + "," + (row.perPixelOnly ? "per-pixel" : "default") +
               "," + std::to_string(row.trianglesSubmitted) + "," + config::formatFixed(row.timing.medianMs, 3) + "," +
               config::formatFixed(row.timing.p90Ms, 3) + "," + config::formatFixed(row.timing.cpuMedianMs, 3) + "," +
               config::formatFixed(row.timing.mtrianglesPerS, 2) + "," +
               config::formatFixed(row.timing.mpixelsPerS, 2) + "," + config::formatFixed(r.vertexBytesPerTriangle, 2) +
               "," + config::formatFixed(r.indexBytesPerTriangle, 2) + "\n";
    return csv;
}

void print(const bench::gl::DrawBenchResult& r, const bench::gl::DrawBenchOptions& o) {
    const glm::dvec3 e = r.view.eye;
    std::cout << "draw-bench: " << r.triangles << " triangles, " << o.resolution << " x " << o.resolution << ", "
              << config::formatFixed(o.fovDeg, 3) << " deg vertical field of view, eye (" << config::formatFixed(e.x, 3)
              << ", " << config::formatFixed(e.y, 3) << ", " << config::formatFixed(e.z, 3) << ") m, "
              << config::formatFixed(r.view.distance, 3) << " m from the bounding sphere's centre"
              << " (radius " << config::formatFixed(r.view.radius, 3) << " m)\n"
              << "GL_RENDERER: " << r.glRenderer << "\n"
              << "GPU memory per triangle: " << config::formatFixed(r.vertexBytesPerTriangle, 2) << " vertex bytes, "
              << config::formatFixed(r.indexBytesPerTriangle, 2) << " index bytes\n\n"
              << "| back faces | lighting | triangles submitted | median ms | p90 ms | CPU ms (median) | Mtriangles/s "
                 "| Mpixels/s |\n"
              << "| --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const bench::gl::DrawBenchRow& row : r.rows)
        std::cout << "| " << (row.cullBackFaces ? "culled" : "drawn (culling off)") << " | "
                  << (row.perPixelOnly ? "per pixel only" : "default") << " | " << row.trianglesSubmitted << " | "
                  << config::formatFixed(row.timing.medianMs, 2) << " | " << config::formatFixed(row.timing.p90Ms, 2)
                  << " | " << config::formatFixed(row.timing.cpuMedianMs, 2) << " | "
                  << config::formatFixed(row.timing.mtrianglesPerS, 1) << " | "
                  << config::formatFixed(row.timing.mpixelsPerS, 1) << " |\n";
}

}  // namespace

int runDrawBench(const std::vector<std::string>& words) {
    const Args args(words, {"compare-lighting"});
    args.expectFlags({"frames", "warmup", "resolution", "fov", "csv", "images", "compare-lighting"});
    const std::string source = args.positional(0, "the scene (glTF/GLB, scene.json or its folder)");
    if (args.positional().size() > 1)
        throw Error("draw-bench: unexpected argument '" + args.positional()[1] + "' (expected one scene)");
    bench::gl::DrawBenchOptions options;
    options.frames = static_cast<int>(args.integer("frames", options.frames, 1, 100000));
    options.warmup = static_cast<int>(args.integer("warmup", options.warmup, 0, 100000));
    options.resolution = static_cast<int>(args.integer("resolution", options.resolution, 16, 8192));
    options.fovDeg = args.number("fov", options.fovDeg, 1.0, 170.0);
    if (auto dir = args.get("images")) options.imageDir = *dir;
    options.compareLighting = args.has("compare-lighting");
    const scenes::Scene scene = scenes::loadSceneFile(source);
    for (const std::string& warning : scene.warnings) std::cerr << "warning: " << warning << "\n";
    if (scene.objects.empty()) throw Error(source + ": no objects to draw (expected a scene with geometry)");
    const bench::gl::DrawBenchResult result = bench::gl::runDrawBench(scene, options);
    print(result, options);
    if (auto csv = args.get("csv")) scenes::writeBytesAtomically(*csv, csvText(result));
    return 0;
}

}  // namespace cavewall::tools
