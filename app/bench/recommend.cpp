#include "app/bench/recommend.h"

#include "app/bench/metrics.h"
#include "app/bench/report.h"
#include "app/bench/scale.h"
#include "config/json_reader.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cavewall::bench {

namespace {

using config::formatNumber;

// Three significant digits: enough to read the reason, as bench.md's cells do.
std::string short3(double v) {
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", v);
    return text;
}

bool takesPart(const RecommendRow& r) {
    return std::isfinite(r.frameMs) && r.frameMs > 0.0 && !std::isnan(r.psnrDb) && !std::isnan(r.flipMean);
}

// Marks the rows on the front of one error (lower is better) against the median frame time.
void markFront(const std::vector<RecommendRow>& rows, double (*error)(const RecommendRow&), std::vector<bool>& front) {
    std::vector<TradeOff> points;
    std::vector<std::size_t> rowOf;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!takesPart(rows[i])) continue;
        points.push_back({rows[i].frameMs, error(rows[i])});
        rowOf.push_back(i);
    }
    for (std::size_t k : paretoFront(points)) front[rowOf[k]] = true;
}

std::string kindClause(const std::vector<RecommendRow>& rows, const std::vector<bool>& front) {
    bool flatOnFront = false, depthOnFront = false, flatMeasured = false;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (!rows[i].walls) continue;
        const bool flat = rows[i].kind == walls::WallKind::Flat;
        flatMeasured = flatMeasured || flat;
        flatOnFront = flatOnFront || (flat && front[i]);
        depthOnFront = depthOnFront || (!flat && front[i]);
    }
    if (depthOnFront && flatMeasured && !flatOnFront) return "; depth walls are on the front and flat walls are not";
    return "";
}

}  // namespace

std::vector<bool> onFront(const std::vector<RecommendRow>& rows) {
    std::vector<bool> front(rows.size(), false);
    markFront(
        rows, [](const RecommendRow& r) { return -r.psnrDb; }, front);
    markFront(
        rows, [](const RecommendRow& r) { return r.flipMean; }, front);
    return front;
}

Recommendation recommendWalls(const std::vector<RecommendRow>& rows, const RecommendRule& rule) {
    const std::vector<bool> front = onFront(rows);
    std::vector<std::size_t> candidates;
    double bestPsnr = -INFINITY;
    for (std::size_t i = 0; i < rows.size(); ++i)
        if (rows[i].walls && front[i]) {
            candidates.push_back(i);
            bestPsnr = std::max(bestPsnr, rows[i].psnrDb);
        }
    if (candidates.empty()) return {std::nullopt, "no walls mode is on the front"};
    std::vector<std::size_t> eligible;
    bool stereo = true;
    for (std::size_t i : candidates)
        if (rows[i].psnrDb >= bestPsnr - rule.psnrWithinDb) {
            eligible.push_back(i);
            stereo = stereo && rows[i].stereoArcmin.has_value();
        }
    const std::size_t withinPsnr = eligible.size();
    double lowestStereo = INFINITY;
    if (stereo) {
        for (std::size_t i : eligible) lowestStereo = std::min(lowestStereo, *rows[i].stereoArcmin);
        std::erase_if(eligible,
                      [&](std::size_t i) { return *rows[i].stereoArcmin > lowestStereo + rule.stereoWithinArcmin; });
    }
    std::size_t pick = eligible.front();
    for (std::size_t i : eligible)
        if (rows[i].frameMs < rows[pick].frameMs) pick = i;
    const RecommendRow& r = rows[pick];
    auto modes = [](std::size_t n) { return std::to_string(n) + (n == 1 ? " walls mode" : " walls modes"); };
    const std::string psnrClause = " on the front within " + formatNumber(rule.psnrWithinDb) +
                                   " dB of the best pooled PSNR (" + short3(bestPsnr) + " dB)";
    std::string reason = stereo
                             ? "fastest of " + modes(eligible.size()) + " within " +
                                   formatNumber(rule.stereoWithinArcmin) + " arcmin of the lowest mean stereo error (" +
                                   short3(lowestStereo) + " arcmin), among " + modes(withinPsnr) + psnrClause
                             : "fastest of " + modes(withinPsnr) + psnrClause;
    reason += ": " + short3(r.frameMs) + " ms median, " + short3(r.psnrDb) + " dB pooled, FLIP mean " +
              short3(r.flipMean) + (stereo ? ", stereo error " + short3(*r.stereoArcmin) + " arcmin" : std::string()) +
              kindClause(rows, front);
    return {pick, reason};
}

std::vector<RecommendRow> recommendRows(const BenchReport& report) {
    std::vector<RecommendRow> rows;
    for (std::size_t i = 0; i < report.modes.size(); ++i) {
        const ModeResult& m = report.modes[i];
        const bool compared = m.error.frames > 0 || i == 0;  // the reference compares with itself
        RecommendRow r{.label = modeLabel(m),
                       .walls = m.mode == Mode::Walls && m.sceneTag.empty() && !m.onDemand,
                       .kind = m.wallKind,
                       .frameMs = m.frameMs.p50,
                       .psnrDb = compared ? m.error.psnrDb : NAN,
                       .flipMean = compared ? m.error.flipMean : NAN,
                       .stereoArcmin = std::nullopt};
        if (m.error.stereoMeasured) r.stereoArcmin = m.error.stereo.meanArcmin();
        rows.push_back(std::move(r));
    }
    return rows;
}

namespace {

RecommendRow scaleRow(const ScaleRow& r) {
    const bool walls =
        r.mode == ScaleMode::Walls || r.mode == ScaleMode::WallsBudget || r.mode == ScaleMode::DepthWalls;
    const bool compared = r.comparedFrames > 0 || r.mode == ScaleMode::Full;
    RecommendRow row{.label = std::string(toString(r.mode)),
                     .walls = walls,
                     .kind = r.mode == ScaleMode::DepthWalls ? walls::WallKind::Depth : walls::WallKind::Flat,
                     .frameMs = r.frameMs.p50,
                     .psnrDb = compared ? r.psnrDb : NAN,
                     .flipMean = compared ? r.flipMean : NAN,
                     .stereoArcmin = std::nullopt};
    if (r.stereoMeasured) row.stereoArcmin = r.stereo.meanArcmin();
    return row;
}

}  // namespace

std::vector<std::string> scaleRecommendedLines(const ScaleReport& report) {
    std::vector<std::size_t> sizes;
    for (const ScaleRow& r : report.rows)
        if (std::find(sizes.begin(), sizes.end(), r.targetTriangles) == sizes.end()) sizes.push_back(r.targetTriangles);
    std::vector<std::string> lines;
    for (std::size_t size : sizes) {
        std::vector<RecommendRow> rows;
        std::size_t triangles = 0;
        for (const ScaleRow& r : report.rows)
            if (r.targetTriangles == size) {
                rows.push_back(scaleRow(r));
                triangles = r.triangles;
            }
        const Recommendation rec = recommendWalls(rows);
        lines.push_back("recommended (" + formatNumber(static_cast<double>(triangles) / 1e6) + " M triangles): " +
                        (rec.row ? rows[*rec.row].label : std::string("none")) + " (" + rec.reason + ")");
    }
    return lines;
}

void recommend(BenchReport& report) {
    const Recommendation r = recommendWalls(recommendRows(report));
    report.recommended = r.row;
    report.recommendedReason = r.reason;
}

std::string recommendedLine(const BenchReport& report) {
    const std::optional<std::size_t> i = report.recommended;
    if (!i || *i >= report.modes.size()) return "recommended: none (" + report.recommendedReason + ")";
    std::string line = "recommended: " + modeLabel(report.modes[*i]) + " (#" + std::to_string(*i + 1) + "; " +
                       report.recommendedReason;
    if (!report.resolution.empty()) line += "; at " + report.resolution;
    return line + ")";
}

}  // namespace cavewall::bench
