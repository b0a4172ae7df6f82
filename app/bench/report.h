#pragma once
// The results of `cavewall bench` and their writers: bench.csv, bench_screens.csv, bench.md
// (also printed) and bench.png (app/bench/report_plot.h, drawn by gnuplot).
//
// One ModeResult per mode of the run. Times are milliseconds per frame (all screens), over the
// timed frames. Errors are against the full-geometry image of the same frame, eye and screen
// (app/bench/metrics.h), pooled over the compared frames: rankings (the figure lines, the Pareto
// front and the plot) use the pooled PSNR (or its RMSE), never the capped mean. The "cells"
// mode (cell culling, no textures) is the control: every mode is also given relative to it.
// Counts are means per frame.

#include "app/bench/metrics.h"
#include "app/run_options.h"

#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::bench {

struct ScreenResult {
    std::string screen;  // display screen name
    ImageError error;
    TimeStats cpuMs;                          // wall-clock CPU ms of the screen's views per frame
    double triangles = 0.0, drawCalls = 0.0;  // means per frame
};

// One timed frame of a mode, as bench_frames.csv lists it.
struct FrameSample {
    double frameMs = 0.0, triangles = 0.0, drawCalls = 0.0;
    double uploadedMB = 0.0;    // wall texture MB uploaded in the frame
    int texturesOverAlpha = 0;  // drawn textures whose exact error exceeds alpha
    // Clusters held to a frame time (hierarchy/cluster_budget.h; 0 otherwise): the predicted cost
    // of what the frame drew, the frame time the controller predicted before drawing it and the
    // floor, the cheapest selection's frame time.
    double predictedMs = 0.0, predictedFrameMs = 0.0, floorMs = 0.0;
    int geometryFallbacks = 0;  // walls drawn as geometry for want of a texture
                                // (FrameResult::geometryFallbacks)
    int keptFallbacks = 0;      // walls drawing the textures they drew last for want of the
                                // wanted ones (paged modes)
    int texturesBaked = 0;      // baking on demand: textures baked so far (running total)
};

// The on-demand mode's figures: the walk from an empty, private bake cache with
// the background baker (`cavewall run --bake-on-demand`). Fallbacks are wall-frames: a wall
// drawn as geometry in one frame for want of a texture counts once.
struct OnDemandFigures {
    double firstFrameSeconds = 0.0;  // planning the walls, keying the empty cache, building the
                                     // walkthrough and drawing the first frame (the scene loaded)
    long geometryFallbacks = 0;      // over the timed frames
    int fallbackFrames = 0;          // timed frames with at least one
    int fallbacksUntilFrame = 0;     // 1 + the index of the last timed frame with one (0: none)
    double firstQuarterFallbacks = 0.0, lastQuarterFallbacks = 0.0;  // per frame, the first and
        // last quarter of the timed frames (both 0 without frames)
    int texturesMissingAtStart = 0;  // the plan's textures (the cache is empty)
    int texturesBaked = 0;           // baked by the end of the run
    std::string cache;               // the private cache folder
};

// Fills the fallback counts of `figures` from the timed frames (the rest is left as is).
void countFallbacks(const std::vector<FrameSample>& frames, OnDemandFigures& figures);

// What a mode draws (app/bench/gl/driver.h lists the modes).
enum class Mode { Full, Cells, CellsLayer, Near, Walls, Clusters };

// "full" | "cells" | "cells+layer" | "near" | "walls" | "clusters", as the mode column of bench.csv.
std::string_view toString(Mode mode);

struct ModeResult {
    Mode mode = Mode::Full;
    double alphaDeg = 0.0;                             // walls modes; 0 otherwise
    std::optional<app::Transition> transition;         // walls modes; none otherwise
    walls::WallKind wallKind = walls::WallKind::Flat;  // walls modes: flat or depth walls (--walls)
    bool paged = false;                                // walls modes: paged from a cold start (`cavewall run`'s paging)
    double lodPixels = 0.0;                            // level-of-detail tolerance in pixels; 0: full detail
    std::size_t triangleBudget = 0;                    // per frame (with levels of detail); 0: none
    double frameBudgetMs = 0.0;                        // frame-time target of the budget controller; 0: none
    TimeStats frameMs, cpuMs, gpuMs;
    double speedup = 1.0;  // full-geometry frame_ms_p50 / this mode's
    // Against the alternative a user would pick, full geometry with levels of detail at the
    // bench's tolerance (compareWithLodBaseline): its frame_ms_p50 / this mode's; NaN without it.
    double speedupLod = std::numeric_limits<double>::quiet_NaN();
    ImageError error;                              // all screens
    FlipMap flipWorst;                             // the FLIP map of the compared image with the highest mean
    std::vector<ImageErrorRecord> comparedImages;  // every compared image's PSNR and FLIP mean
    // Against the control (compareWithControl): pooled PSNR minus the control's (dB, > 0: less
    // error) and FLIP mean over the control's (< 1: less error). NaN without a control.
    double psnrGainDb = std::numeric_limits<double>::quiet_NaN();
    double flipRatio = std::numeric_limits<double>::quiet_NaN();
    double maxErrDeg = 0.0;           // worst angular error of a drawn texture (0 without textures)
    double maxErrPx = 0.0;            // the same in screen pixels
    double maxLodErrPx = 0.0;         // worst geometric error of a drawn level of detail, pixels
    double meanLodTolerancePx = 0.0;  // the frames' mean LOD tolerance (above lodPixels where the
                                      // budget raised it)
    int overBudgetFrames = 0;         // frames whose coarsest levels still exceeded the budget
    double triangles = 0.0, drawCalls = 0.0;
    int textures = 0;     // baked textures of the plan
    double texels = 0.0;  // sum of their base-level texels
    double diskMB = 0.0;  // bytes of the baked files / 1e6
    double gpuMB = 0.0;   // peak resident texture MB (the pager's count)
    long misses = 0;      // wanted textures not resident, over the run
    std::vector<ScreenResult> screens;
    std::vector<FrameSample> frames;  // every timed frame, in path order
    // p99/p50 of the triangles drawn per frame: how much the path's load alone varies, to
    // read next to the frame time's p99/p50 (the rest is stalls and noise).
    double loadRatio = 0.0;
    // Textures drawn with an exact error above alpha, summed over the timed frames (the bound
    // promises 0), and the wall texture MB uploaded per frame (p50, p95, p99 and mean; 0 when every texture was resident before the timed frames).
    long texturesOverAlpha = 0;
    TimeStats uploadedMB;
    // The scene the mode drew when it is not the bench's own (`bench --compare-scene`: the same
    // model with other cells and walls, on the same eye path): a short name, "" for the bench's.
    std::string sceneTag;
    // Baking on demand from a cold, private cache (`bench --on-demand`); a walls mode.
    std::optional<OnDemandFigures> onDemand;
};

struct BenchReport {
    std::vector<std::string> header;  // settings and machine, one line each
    std::vector<ModeResult> modes;    // the full-geometry reference first
    double noiseFloorRatio = 0.0;     // p99/p50 of one frame drawn again and again (0: not measured)
    double noiseFloorP95Ratio = 0.0;  // p95/p50 of the same (0: not measured)
    std::string resolution;           // "1024x1024 per screen, mono": stated with every figure line
    // The recommended walls mode (app/bench/recommend.h; recommend() fills it): an index into
    // `modes`, none when no walls mode is on the front, and the rule's reason.
    std::optional<std::size_t> recommended;
    std::string recommendedReason;
    // The control when the caller names it, an index into `modes` (the demo: its cells run at
    // the walls' level of detail); none: controlMode's rule.
    std::optional<std::size_t> control;
    // writeReport also writes each mode's worst image and full geometry's of the same view
    // (worst_N.png, worst_N_full.png; --save-worst).
    bool saveWorst = false;
};

// Fills report.recommended and recommendedReason by app/bench/recommend.h's rule
// (app/bench/recommend.cpp).
void recommend(BenchReport& report);

// "recommended: walls flat a=10 blend lod 1px (#7; fastest of ...; at 128x128 per screen, mono)", or
// "recommended: none (no walls mode is on the front)" (app/bench/recommend.cpp).
std::string recommendedLine(const BenchReport& report);

// `v` with `decimals` digits after the point (no exponent); inf, -inf and nan spelled so.
std::string fixed(double v, int decimals = 1);

// The CSV header line (without newline): mode, alpha, transition and the frame times first;
// the last column, "recommended", is 1 on the recommended walls mode's row and 0 elsewhere.
std::string csvHeader();
// One CSV line (without newline); numbers in C locale, "inf" for infinite PSNR.
std::string csvRow(const ModeResult& m, bool recommended = false);
// Markdown: the header lines as a list, then one table row per mode.
std::string markdownReport(const BenchReport& report);

// The control of `report`: report.control when set, else its first "cells" mode without levels
// of detail or budgets; null when there is none.
const ModeResult* controlMode(const BenchReport& report);

// The baseline a user would pick instead of walls: the first full-geometry mode with levels of
// detail (the bench's --lod tolerance); null when the bench ran without levels of detail.
const ModeResult* lodBaseline(const BenchReport& report);

// Fills every mode's speedupLod against lodBaseline (NaN without one).
void compareWithLodBaseline(BenchReport& report);

// The control `m` is judged against: report.control when set, else the first "cells" mode of
// the bench scene at m's level-of-detail tolerance without budgets (what the textures add at the
// same tolerance), else controlMode; null when there is none.
const ModeResult* controlFor(const BenchReport& report, const ModeResult& m);

// Fills every mode's psnrGainDb and flipRatio against its control (controlFor; NaN without one;
// a control FLIP mean of 0 gives a NaN or infinite ratio).
void compareWithControl(BenchReport& report);

// Figures read off the table, one line each, every line stating the report's resolution (no
// line judges a figure against a target; docs/benchmarking.md does): textures drawn over alpha
// in the walls modes; the fastest walls mode of the bench's own scene at alpha <= 10 with
// levels of detail and pooled PSNR >= 32 dB (else the closest in PSNR), its speed-up, FLIP mean
// against the control's, frame-time p99/p50 against the noise floor, triangles' and uploads'
// p99/p50, and its median against the near limit's and full geometry's; each paged mode's
// uploads p99/p50; the limit's median against the control plus one textured full-screen layer,
// when the report has the "cells+layer" mode; clusterBudgetLines; every compare-scene mode's
// speed-up against the same mode of the bench's scene; and the on-demand mode's first frame,
// fallbacks, textures baked and frame-time p99/p50 against the noise floor.
std::vector<std::string> figureLines(const BenchReport& report);

// A least-squares line y = intercept + slope x through (x[i], y[i]); zeros for fewer than two
// points or all x equal. r2: the share of y's variance the line explains.
struct LineFit {
    double slope = 0.0, intercept = 0.0, r2 = 0.0;
    std::size_t points = 0;
};
LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y);

// A mode held to a frame time (frameBudgetMs > 0): its p95 frame time over the budget; the
// median floor of its frames (clusters: the cheapest selection's frame time, FrameSample::floorMs
// > 0 only; 0 when none has one), and whether the budget is feasible (no floor above it).
double p95OverBudget(const ModeResult& m);
double medianFloorMs(const ModeResult& m);

// Maciel & Shirley's (1995) frame budget for every clusters mode held to a frame time, one line
// each: p50 and p95 frame ms, p95 over the budget (the timed frames follow the warm-up), the
// floor and whether the budget is feasible (a budget below the floor is said to be infeasible),
// the predicted against the measured frame time (median and p95 of |measured - predicted| /
// measured), the pooled PSNR and FLIP mean, and the noise floor's p95/p50 beside them; then one
// line fitting measured = a + b predicted over the frames of every clusters mode (b = 1: the
// costs are right at the display's resolution; a: the fixed part of a frame). Empty without
// such modes.
std::vector<std::string> clusterBudgetLines(const BenchReport& report);

// Writes bench.csv, bench_screens.csv, bench_frames.csv (every timed frame of every mode),
// bench_compared.csv (every compared image of every mode: frame, screen, eye, PSNR, FLIP mean),
// bench.md, bench.png and flip_worst_N.png (the FLIP map of mode N's worst image, N as the "#"
// column of bench.md, for every mode that compared images; with report.saveWorst also
// worst_N.png and worst_N_full.png, the two images that map compares) into `folder` (created).
// Returns the files written.
std::vector<std::filesystem::path> writeReport(const std::filesystem::path& folder, const BenchReport& report);

// The transition column of bench.csv: "none", "blend", "warp", "blend paged" or
// "blend on demand".
std::string transitionLabel(const ModeResult& m);

// "walls flat a=10 blend", "walls depth a=10 blend", "full", "walls flat a=30 blend lod 1px budget
// 40000", "walls flat a=10 blend [auto]" (a --compare-scene mode), ...: the mode's label in tables
// and the plot legend; walls modes name their kind (walls::wallKindName).
std::string modeLabel(const ModeResult& m);

}  // namespace cavewall::bench
