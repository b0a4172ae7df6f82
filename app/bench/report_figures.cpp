// The figure lines of the bench report (report.h, figureLines): what the table says of the
// recommended walls mode, the limit, the budgets, the compare scenes and baking on demand.
#include "app/bench/report.h"
#include "app/bench/report_text.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

namespace cavewall::bench {

using detail::num;

namespace {

// The first mode named `mode` drawing at the same level-of-detail tolerance as `like`.
const ModeResult* findMode(const BenchReport& report, Mode mode, const ModeResult& like) {
    for (const ModeResult& m : report.modes)
        if (m.mode == mode && m.lodPixels == like.lodPixels && m.triangleBudget == 0 && m.frameBudgetMs == 0.0)
            return &m;
    return nullptr;
}

}  // namespace

namespace {

// ", Rx the noise floor (one frame drawn again and again: F)" for a frame-time p99/p50 `ratio`
// against the bench's noise floor `floor` (0: not measured).
std::string noiseFloorClause(double ratio, double floor) {
    if (!(floor > 0.0)) return " (no noise floor measured)";
    return ", " + num(ratio / floor, 3) + "x the noise floor (one frame drawn again and again: " + num(floor, 3) + ")";
}

// The wall pass's yardstick: the limit (near geometry and bare wall quads) against the control
// plus one textured full-screen layer, both at full detail.
std::optional<std::string> layerLine(const BenchReport& report) {
    const ModeResult* control = controlMode(report);
    if (!control) return std::nullopt;
    const ModeResult* layer = findMode(report, Mode::CellsLayer, *control);
    const ModeResult* near = findMode(report, Mode::Near, *control);
    if (!layer || !near) return std::nullopt;
    return "the limit (near geometry and bare wall quads) takes " + num(near->frameMs.p50, 3) + " ms (p50) against " +
           num(layer->frameMs.p50, 3) + " ms for the control plus one textured full-screen layer (" +
           num(control->frameMs.p50, 3) + " ms without the layer)";
}

// "figures: its FLIP mean is R x the control's at the same tolerance (cells, no textures, LOD
// 1 px; a against b), R' x the control at full detail's (c)": the second clause only where the
// two controls differ.
std::string controlLine(const BenchReport& report, const ModeResult& best) {
    const ModeResult* same = controlFor(report, best);
    const ModeResult* full = controlMode(report);
    std::string line = "figures: its FLIP mean is " + num(best.flipRatio, 3) + "x the control's";
    line += same->lodPixels > 0.0 ? " at the same tolerance (cells, no textures, LOD " + num(same->lodPixels) + " px; "
                                  : " (cells, no textures; ";
    line += num(best.error.flipMean, 3) + " against " + num(same->error.flipMean, 3) + ")";
    if (full && full != same)
        line += ", " + num(best.error.flipMean / full->error.flipMean, 3) + "x the control's at full detail (" +
                num(full->error.flipMean, 3) + ")";
    return line;
}

std::vector<std::string> wallsFigureLines(const BenchReport& report) {
    // The walls mode the figures describe: the fastest at alpha <= 10 degrees with levels of
    // detail and a pooled PSNR >= 32 dB (docs/benchmarking.md).
    constexpr double kAlpha = 10.0, kPsnr = 32.0;
    std::vector<std::string> lines;
    long overAlpha = 0;
    int wallsModes = 0;
    for (const ModeResult& m : report.modes)
        if (m.mode == Mode::Walls) {
            overAlpha += m.texturesOverAlpha;
            ++wallsModes;
        }
    if (wallsModes > 0)
        lines.push_back("figures: textures drawn over alpha in " + std::to_string(wallsModes) +
                        " walls modes: " + std::to_string(overAlpha));
    const ModeResult* best = nullptr;     // fastest eligible
    const ModeResult* closest = nullptr;  // best pooled PSNR among the candidates
    for (const ModeResult& m : report.modes) {
        if (m.mode != Mode::Walls || m.alphaDeg > kAlpha || m.lodPixels <= 0.0 || !m.sceneTag.empty() || m.onDemand)
            continue;
        if (!closest || m.error.psnrDb > closest->error.psnrDb) closest = &m;
        if (m.error.psnrDb >= kPsnr && (!best || m.speedup > best->speedup)) best = &m;
    }
    if (!closest) {
        lines.push_back("figures: no walls mode at alpha <= 10 with levels of detail");
        return lines;
    }
    if (!best) {
        lines.push_back(
            "figures: no walls mode at alpha <= 10 with levels of detail reaches a pooled PSNR >= 32 dB; "
            "the closest, " +
            modeLabel(*closest) + ", has " + num(closest->error.psnrDb, 3) + " dB pooled at a speed-up of " +
            num(closest->speedup, 3));
        best = closest;
    } else {
        lines.push_back("figures: fastest walls mode at alpha <= 10 with levels of detail and pooled PSNR >= 32 dB: " +
                        modeLabel(*best) + ", speed-up " + num(best->speedup, 3) + ", PSNR " +
                        num(best->error.psnrDb, 3) + " dB pooled (worst frame " + num(best->error.worstFramePsnrDb, 3) +
                        " dB)");
    }
    if (!std::isnan(best->flipRatio)) lines.push_back(controlLine(report, *best));
    const double ratio = best->frameMs.p50 > 0 ? best->frameMs.p99 / best->frameMs.p50 : 0.0;
    std::string stability = "figures: its frame time p99/p50 is " + num(ratio, 3);
    stability += noiseFloorClause(ratio, report.noiseFloorRatio);
    stability += "; per-frame work p99/p50: triangles " + num(best->loadRatio, 3);
    stability += best->uploadedMB.p50 > 0.0
                     ? ", texture MB uploaded " + num(best->uploadedMB.p99 / best->uploadedMB.p50, 3)
                     : ", texture MB uploaded p50 0, p99 " + num(best->uploadedMB.p99, 3) +
                           " (a ratio needs uploads in the median frame)";
    lines.push_back(stability);
    // Uploads happen only where textures page: the paged modes.
    for (const ModeResult& m : report.modes)
        if (m.mode == Mode::Walls && m.paged && m.uploadedMB.p50 > 0.0)
            lines.push_back("figures: " + modeLabel(m) + ": texture MB uploaded per frame p99/p50 " +
                            num(m.uploadedMB.p99 / m.uploadedMB.p50, 3) + " (" + num(m.uploadedMB.p99, 3) + " / " +
                            num(m.uploadedMB.p50, 3) + ")");
    if (const ModeResult* near = findMode(report, Mode::Near, *best); near && near->frameMs.p50 > 0) {
        const double limit = best->frameMs.p50 / near->frameMs.p50;
        lines.push_back("figures: its median frame time is " + num(limit, 3) +
                        "x the limit's, near geometry plus bare wall quads at the same level of detail (" +
                        num(best->frameMs.p50, 3) + " ms against " + num(near->frameMs.p50, 3) + " ms)");
    }
    if (const ModeResult* full = findMode(report, Mode::Full, *best); full && full->frameMs.p50 > 0)
        lines.push_back("figures: against full geometry at the same level of detail (" + modeLabel(*full) + ", " +
                        num(full->frameMs.p50, 3) + " ms) its speed-up is " +
                        num(full->frameMs.p50 / best->frameMs.p50, 3) +
                        ": what the walls add on top of the levels of detail");
    return lines;
}

// The same walls mode (alpha, transition, levels of detail, budgets) on the bench's own scene.
const ModeResult* ownSceneMode(const BenchReport& report, const ModeResult& like) {
    for (const ModeResult& m : report.modes)
        if (m.mode == Mode::Walls && m.sceneTag.empty() && !m.onDemand && !m.paged && m.alphaDeg == like.alphaDeg &&
            m.transition == like.transition && m.lodPixels == like.lodPixels &&
            m.triangleBudget == like.triangleBudget && m.frameBudgetMs == like.frameBudgetMs)
            return &m;
    return nullptr;
}

// A compare scene's walls (automatic) against the bench scene's (hand-placed), in the same
// seconds: speed-ups over the same full-geometry run, and their ratio.
std::vector<std::string> compareLines(const BenchReport& report) {
    std::vector<std::string> lines;
    for (const ModeResult& m : report.modes) {
        if (m.sceneTag.empty() || m.mode != Mode::Walls) continue;
        const ModeResult* own = ownSceneMode(report, m);
        if (!own || own->speedup <= 0.0) continue;
        const double ratio = m.speedup / own->speedup;
        lines.push_back("figures: " + modeLabel(m) + " against " + modeLabel(*own) + ": speed-up " + num(m.speedup, 3) +
                        " against " + num(own->speedup, 3) + " (ratio " + num(ratio, 3) + "), PSNR " +
                        num(m.error.psnrDb, 3) + " against " + num(own->error.psnrDb, 3) + " dB pooled, FLIP mean " +
                        num(m.error.flipMean, 3) + " against " + num(own->error.flipMean, 3) + ", " +
                        std::to_string(m.textures) + " against " + std::to_string(own->textures) + " textures, " +
                        num(m.diskMB, 4) + " against " + num(own->diskMB, 4) + " MB on disk, textures over alpha " +
                        std::to_string(m.texturesOverAlpha) + " against " + std::to_string(own->texturesOverAlpha));
    }
    return lines;
}

// Baking on demand from a cold cache.
std::vector<std::string> onDemandLines(const BenchReport& report) {
    std::vector<std::string> lines;
    for (const ModeResult& m : report.modes) {
        if (!m.onDemand) continue;
        const OnDemandFigures& f = *m.onDemand;
        const double ratio = m.frameMs.p50 > 0 ? m.frameMs.p99 / m.frameMs.p50 : 0.0;
        std::string line =
            "figures: " + modeLabel(m) + " from an empty cache: first frame " + num(f.firstFrameSeconds, 3) +
            " s after the scene's load; " + std::to_string(f.geometryFallbacks) +
            " geometry fallbacks (wall-frames) in " + std::to_string(f.fallbackFrames) + " of " +
            std::to_string(m.frames.size()) + " frames, the last in frame " + std::to_string(f.fallbacksUntilFrame) +
            " (counted from 1), " + num(f.firstQuarterFallbacks, 3) + " per frame in the first quarter and " +
            num(f.lastQuarterFallbacks, 3) + " in the last; " + std::to_string(f.texturesBaked) + " of " +
            std::to_string(f.texturesMissingAtStart) + " textures baked; frame p99/p50 " + num(ratio, 3);
        line += noiseFloorClause(ratio, report.noiseFloorRatio);
        if (const ModeResult* warm = ownSceneMode(report, m); warm && warm->frameMs.p50 > 0)
            line += "; p50 " + num(m.frameMs.p50, 3) + " ms against " + num(warm->frameMs.p50, 3) + " ms for " +
                    modeLabel(*warm) + " with every texture resident (not the same seconds)";
        lines.push_back(line);
    }
    return lines;
}

}  // namespace

LineFit fitLine(const std::vector<double>& x, const std::vector<double>& y) {
    LineFit f;
    const std::size_t n = std::min(x.size(), y.size());
    if (n < 2) return f;
    double mx = 0.0, my = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        mx += x[i];
        my += y[i];
    }
    mx /= static_cast<double>(n);
    my /= static_cast<double>(n);
    double sxx = 0.0, sxy = 0.0, syy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sxx += (x[i] - mx) * (x[i] - mx);
        sxy += (x[i] - mx) * (y[i] - my);
        syy += (y[i] - my) * (y[i] - my);
    }
    if (sxx <= 0.0) return f;
    f.points = n;
    f.slope = sxy / sxx;
    f.intercept = my - f.slope * mx;
    f.r2 = syy > 0.0 ? sxy * sxy / (sxx * syy) : 1.0;
    return f;
}

double p95OverBudget(const ModeResult& m) { return m.frameBudgetMs > 0.0 ? m.frameMs.p95 / m.frameBudgetMs : 0.0; }

double medianFloorMs(const ModeResult& m) {
    std::vector<double> floors;
    for (const FrameSample& f : m.frames)
        if (f.floorMs > 0.0) floors.push_back(f.floorMs);
    return floors.empty() ? 0.0 : timeStats(floors).p50;
}

namespace {

std::string clusterBudgetLine(const BenchReport& report, const ModeResult& m) {
    const double ratio = p95OverBudget(m), floor = medianFloorMs(m);
    const bool feasible = floor <= m.frameBudgetMs;
    std::vector<double> errors;
    for (const FrameSample& f : m.frames)
        if (f.predictedFrameMs > 0.0 && f.frameMs > 0.0)
            errors.push_back(std::abs(f.frameMs - f.predictedFrameMs) / f.frameMs);
    const TimeStats e = timeStats(errors);
    std::string line = "figures: " + modeLabel(m) + ": p50 " + num(m.frameMs.p50, 3) + " ms, p95 " +
                       num(m.frameMs.p95, 3) + " ms = " + num(ratio, 3) + "x the budget";
    if (!feasible) line += " (infeasible: the floor is above the budget)";
    line += "; floor (the cheapest selection's frame time, median) " + num(floor, 3) + " ms; predicted frame time " +
            "off by " + num(100.0 * e.p50, 3) + " % (median), " + num(100.0 * e.p95, 3) + " % (p95); " +
            num(m.error.psnrDb, 3) + " dB pooled, FLIP mean " + num(m.error.flipMean, 3);
    if (report.noiseFloorP95Ratio > 0.0) line += "; noise floor p95/p50 " + num(report.noiseFloorP95Ratio, 3);
    return line;
}

}  // namespace

std::vector<std::string> clusterBudgetLines(const BenchReport& report) {
    std::vector<std::string> lines;
    std::vector<double> predicted, measured;
    for (const ModeResult& m : report.modes) {
        if (m.mode != Mode::Clusters || m.frameBudgetMs <= 0.0) continue;
        lines.push_back(clusterBudgetLine(report, m));
        for (const FrameSample& f : m.frames) {
            predicted.push_back(f.predictedMs);
            measured.push_back(f.frameMs);
        }
    }
    if (lines.empty()) return lines;
    const LineFit fit = fitLine(predicted, measured);
    lines.push_back("figures: clusters' measured frame ms against their predicted cost over " +
                    std::to_string(fit.points) + " frames: measured = " + num(fit.intercept, 3) + " + " +
                    num(fit.slope, 3) + " x predicted (r2 " + num(fit.r2, 2) +
                    "; slope 1: the costs are right at this resolution, the intercept is the fixed part)");
    return lines;
}

void countFallbacks(const std::vector<FrameSample>& frames, OnDemandFigures& figures) {
    figures.geometryFallbacks = 0;
    figures.fallbackFrames = 0;
    figures.fallbacksUntilFrame = 0;
    const std::size_t n = frames.size(), quarter = std::max<std::size_t>(1, n / 4);
    double first = 0.0, last = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const int f = frames[i].geometryFallbacks;
        figures.geometryFallbacks += f;
        if (f > 0) {
            ++figures.fallbackFrames;
            figures.fallbacksUntilFrame = static_cast<int>(i) + 1;
        }
        if (i < quarter) first += f;
        if (i + quarter >= n) last += f;
    }
    figures.firstQuarterFallbacks = n > 0 ? first / static_cast<double>(std::min(quarter, n)) : 0.0;
    figures.lastQuarterFallbacks = n > 0 ? last / static_cast<double>(std::min(quarter, n)) : 0.0;
}

std::vector<std::string> figureLines(const BenchReport& report) {
    std::vector<std::string> lines = wallsFigureLines(report);
    if (auto layer = layerLine(report)) lines.push_back("figures: " + *layer);
    for (std::string& line : clusterBudgetLines(report)) lines.push_back(std::move(line));
    for (std::string& line : compareLines(report)) lines.push_back(std::move(line));
    for (std::string& line : onDemandLines(report)) lines.push_back(std::move(line));
    if (!report.resolution.empty())
        for (std::string& line : lines)
            line = "figures (" + report.resolution + "):" + line.substr(std::string("figures:").size());
    return lines;
}

}  // namespace cavewall::bench
