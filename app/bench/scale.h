#pragma once
// The results of `cavewall bench --scale` and their writers: scale.csv,
// scale.md (also printed) and three plots against the model's triangles (scale_ms.png, median
// frame time; scale_mb.png, resident geometry; scale_load.png, time to the first frame).
//
// One ScaleRow per model size and mode. Modes: full geometry (frustum-culled, the whole model
// on the GPU), the near-geometry limit (the viewer's cell and the always-resident structure),
// walls (virtual walls with levels of detail and geometry paging by cell) and, when run, walls
// whose geometry is held to a triangle budget (Maciel & Shirley's (1995) frame budget: the
// levels of detail coarsened just enough, their error in the row's image error). Times are
// milliseconds per frame (all screens) over the timed frames; memory is MB = 2^20 bytes of GPU
// vertex and index buffers (render/gl/scene_gpu.h sizes).

#include "app/bench/metrics.h"

#include <glm/glm.hpp>

#include <cstddef>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::bench {

// DepthWalls: depth walls drawn in the same run as flat ones (`--walls flat,depth`), so that
// their frame-time ratio shares the machine's load of the same seconds. Cells: the control,
// cells without textures (the flat walls' geometry cells, no texture).
// FullLod: full geometry with levels of detail at the walls' tolerance, the alternative a user
// would pick (left out without levels of detail).
enum class ScaleMode { Full, Near, Walls, WallsBudget, DepthWalls, Cells, FullLod };
inline constexpr ScaleMode kScaleModes[] = {ScaleMode::Full,      ScaleMode::FullLod, ScaleMode::Near,
                                            ScaleMode::Cells,     ScaleMode::Walls,   ScaleMode::WallsBudget,
                                            ScaleMode::DepthWalls};
// "full" | "full-lod" | "near" | "cells" | "walls" | "walls-budget" | "walls-depth"
std::string_view toString(ScaleMode mode);

struct ScaleRow {
    std::size_t targetTriangles = 0;  // the --scale entry the plant was generated for
    std::size_t triangles = 0;        // drawn triangles of the whole model (instances counted)
    std::size_t triangleBudget = 0;   // walls-budget: its budget per frame (all views); else 0
    int cells = 0;
    ScaleMode mode = ScaleMode::Full;
    TimeStats frameMs;
    double trianglesPerFrame = 0.0;  // mean drawn per frame (all views)
    // Geometry on the GPU, MB: the most at once over the timed frames. Full and near: the whole
    // model (uploaded at start). Walls: the always-resident shared buffers plus the resident
    // paged mesh groups.
    double residentMB = 0.0;
    double pagedPeakMB = 0.0;                              // walls: the paged groups alone (what paging decides)
    double wholeModelMB = 0.0, largestThreeCellsMB = 0.0;  // yardsticks (walkthrough/gl/walkthrough.h)
    double loadSeconds = 0.0;                              // reading the scene files into memory
    double firstFrameSeconds = 0.0;                        // from the loaded scene to the end of the first frame
    long geometryMisses = 0, geometryPageIns = 0;          // walls: cumulative over the run
    int texturesOverAlpha = 0;                             // walls: the most in a frame
    // Image error against full geometry's image of the same frame (ScaleOptions::compareEvery;
    // full, the reference, and runs without comparisons keep these defaults): compared frames,
    // pooled PSNR over all their pixels (infinite: identical), the worst frame's PSNR and the
    // mean LDR-FLIP (app/bench/metrics.h).
    std::size_t comparedFrames = 0;
    double psnrDb = std::numeric_limits<double>::infinity();
    double worstFramePsnrDb = std::numeric_limits<double>::infinity();
    double flipMean = 0.0;
    double worstImageFlip = 0.0;  // the FLIP mean of the worst compared image (one screen, one eye)
    // On a stereo display: the stereo error of every compared eye's depth against full
    // geometry's (metrics/stereo_error.h, pooled over the compared pixels). Not measured in mono.
    bool stereoMeasured = false;
    metrics::StereoError stereo;
};

struct ScaleReport {
    std::vector<std::string> header;  // lines for the Markdown report
    std::vector<ScaleRow> rows;
};

// Least-squares slope of the median frame ms against millions of triangles for `mode`; NaN
// with fewer than two sizes.
double msPerMillionTriangles(const ScaleReport& report, ScaleMode mode);
// The median frame ms at the largest size over that at the smallest (NaN with one size).
double growth(const ScaleReport& report, ScaleMode mode);

std::string scaleCsv(const ScaleReport& report);
std::string scaleMarkdown(const ScaleReport& report);
// Writes scale.csv, scale.md and the three plots (app/bench/gnuplot.h: one named line per mode)
// into `folder` (created); returns the files.
std::vector<std::filesystem::path> writeScaleReport(const std::filesystem::path& folder, const ScaleReport& report);

// The stamp in a generated plant's folder (DIR/plant-N of --data): the --scale entry the plant
// was generated for and its drawn triangles, so that a folder reused by a later run is known to
// hold that plant and not another model put there.
inline constexpr const char* kPlantStamp = "cavewall-plant.json";

// Writes `folder`'s stamp: the plant in it was generated for `target` and draws `triangles`.
void writePlantStamp(const std::filesystem::path& folder, std::size_t target, std::size_t triangles);

// Checks a reused plant folder before its model is benchmarked as the plant for `target`:
// `triangles` (the loaded model's drawn triangles) must be what the folder's stamp says, and
// the stamp must name `target`. A folder without a stamp (written before stamps were) is
// checked against `generatedTriangles()` (the plant made again in memory) and then stamped.
// Throws cavewall::Error naming the folder, what was expected and what it holds.
void checkPlantFolder(const std::filesystem::path& folder, std::size_t target, std::size_t triangles,
                      const std::function<std::size_t()>& generatedTriangles);

// "2M,8M,32M" (k and M suffixes, plain decimal integers too): triangle targets, each from 1 to
// scenes::kPlantMaxTriangles (the largest plant the generator makes). Throws cavewall::Error
// naming the entry.
std::vector<std::size_t> parseScaleList(const std::string& text);

// The first `metres` of the polyline `points` (all of it when shorter; the last point
// interpolated): the same stretch of walk at every size.
std::vector<glm::dvec3> pathPrefix(const std::vector<glm::dvec3>& points, double metres);

}  // namespace cavewall::bench
