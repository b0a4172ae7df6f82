#pragma once
// The walls mode the bench recommends, read off its results by one stated rule
// (docs/benchmarking.md, "The recommended walls mode"). Pure: a table of modes in, the
// recommendation and its reason out.
//
// The front: a mode is on it when no other mode of the table is at least as fast and at least
// as good, and better in one, in pooled PSNR against median frame time, or in FLIP mean against
// median frame time (the two panels of bench.png). Modes with a non-finite time or error take
// no part. The rule, over the walls modes on the front:
//  1. none on the front: no recommendation;
//  2. eligible: those whose pooled PSNR is within `psnrWithinDb` of the best of them;
//  3. when every eligible mode has a stereo error (stereo displays), those whose mean stereo
//     error is within `stereoWithinArcmin` of the lowest of them stay eligible;
//  4. the fastest eligible mode (lowest median frame time); ties go to the earlier row.
// So depth walls are recommended whenever they are on the front and flat walls are not.

#include "walls/depth_wall.h"

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::bench {

// One row of the table: a mode of the bench, with the figures the rule reads.
struct RecommendRow {
    std::string label;                             // as bench.md names it
    bool walls = false;                            // a walls mode the rule may pick
    walls::WallKind kind = walls::WallKind::Flat;  // walls modes: flat or depth walls
    double frameMs = 0.0;                          // median frame time, all screens
    double psnrDb = 0.0;                           // pooled PSNR against full geometry
    double flipMean = 0.0;                         // LDR-FLIP mean against full geometry
    std::optional<double> stereoArcmin{};          // mean stereo error; none in mono
};

struct RecommendRule {
    double psnrWithinDb = 1.0;  // eligible: pooled PSNR at least the best's minus this, dB
    // In stereo, still eligible: a mean stereo error at most the lowest's plus this, arc
    // minutes; a thousandth of the 1' stereoacuity threshold the stereo error counts against.
    double stereoWithinArcmin = 0.001;
};

struct Recommendation {
    std::optional<std::size_t> row;  // the recommended row; none when no walls mode is on the front
    std::string reason;              // one clause, with the figures it used
};

// Whether each row is on the front (see the header comment), in the table's order.
std::vector<bool> onFront(const std::vector<RecommendRow>& rows);

// The rule above applied to `rows`.
Recommendation recommendWalls(const std::vector<RecommendRow>& rows, const RecommendRule& rule = {});

struct BenchReport;

// The rows of a bench report, in its order: walls modes of the bench's own scene (not baked on
// demand) may be picked; modes that compared no images (but the reference, the first) take no
// part.
std::vector<RecommendRow> recommendRows(const BenchReport& report);

struct ScaleReport;

// `bench --scale`: one "recommended (N M triangles): MODE (reason)" line per model size, the
// rule over that size's rows (walls, walls-budget and walls-depth may be picked; rows that
// compared no images, but full geometry, the reference, take no part).
std::vector<std::string> scaleRecommendedLines(const ScaleReport& report);

}  // namespace cavewall::bench
