#include "app/bench/report.h"

#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"
#include "walls/depth_wall.h"
#include "app/bench/gnuplot.h"
#include "app/bench/report_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <sstream>

namespace cavewall::bench {

namespace {

std::string num(double v, int digits = 6) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (std::isnan(v)) return "nan";
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    return buffer;
}

// The stereo error's CSV cells: mean arc minutes and the share of pixels beyond the
// threshold; nan when it was not measured (mono).
std::string stereoCsv(const ImageError& e) {
    if (!e.stereoMeasured) return "nan,nan";
    return num(e.stereo.meanArcmin()) + "," + num(e.stereo.shareBeyond());
}

// The stereo error's bench.md cell: "mean / % beyond"; "-" when not measured (mono).
std::string stereoCell(const ImageError& e) {
    if (!e.stereoMeasured) return "-";
    return num(e.stereo.meanArcmin(), 3) + " / " + num(100.0 * e.stereo.shareBeyond(), 3);
}

void writeText(const std::filesystem::path& file, const std::string& text) { scenes::writeBytesAtomically(file, text); }

std::string screensCsv(const BenchReport& report) {
    std::string out =
        "mode,alpha_deg,transition,screen,psnr_db,rmse,ssim,cpu_ms_p50,cpu_ms_p95,cpu_ms_p99,triangles,"
        "draw_calls,lod_px,triangle_budget,worst_frame_psnr_db,p5_frame_psnr_db,capped_mean_psnr_db,"
        "flip_mean,flip_share_over_0.1,popping_peak,popping_rms,stereo_mean_arcmin,stereo_beyond_share\n";
    for (const ModeResult& m : report.modes)
        for (const ScreenResult& s : m.screens) {
            const ImageError& e = s.error;
            out += std::string(toString(m.mode)) + "," + num(m.alphaDeg) + "," + transitionLabel(m) + "," + s.screen +
                   "," + num(e.psnrDb) + "," + num(e.rmse) + "," + num(e.ssim) + "," + num(s.cpuMs.p50) + "," +
                   num(s.cpuMs.p95) + "," + num(s.cpuMs.p99) + "," + num(s.triangles) + "," + num(s.drawCalls) + "," +
                   num(m.lodPixels) + "," + std::to_string(m.triangleBudget);
            for (double v : {e.worstFramePsnrDb, e.p5FramePsnrDb, e.meanPsnrDb, e.flipMean, e.flipOverThreshold,
                             e.poppingPeak, e.poppingRms})
                out += "," + num(v);
            out += "," + stereoCsv(e) + "\n";
        }
    return out;
}

// The first mode named `mode` drawing at the same level-of-detail tolerance as `like`.
const ModeResult* findMode(const BenchReport& report, Mode mode, const ModeResult& like) {
    for (const ModeResult& m : report.modes)
        if (m.mode == mode && m.lodPixels == like.lodPixels && m.triangleBudget == 0 && m.frameBudgetMs == 0.0)
            return &m;
    return nullptr;
}

}  // namespace

const ModeResult* controlMode(const BenchReport& report) {
    if (report.control) return &report.modes.at(*report.control);
    for (const ModeResult& m : report.modes)
        if (m.mode == Mode::Cells && m.lodPixels == 0.0 && m.triangleBudget == 0 && m.frameBudgetMs == 0.0) return &m;
    return nullptr;
}

const ModeResult* controlFor(const BenchReport& report, const ModeResult& m) {
    if (report.control) return &report.modes.at(*report.control);
    for (const ModeResult& c : report.modes)
        if (c.mode == Mode::Cells && c.lodPixels == m.lodPixels && c.triangleBudget == 0 && c.frameBudgetMs == 0.0 &&
            c.sceneTag.empty())
            return &c;
    return controlMode(report);
}

void compareWithControl(BenchReport& report) {
    for (ModeResult& m : report.modes)  // the controls' errors are read, never written here
        if (const ModeResult* control = controlFor(report, m)) {
            m.psnrGainDb = m.error.psnrDb - control->error.psnrDb;
            m.flipRatio = m.error.flipMean / control->error.flipMean;
        }
}

const ModeResult* lodBaseline(const BenchReport& report) {
    for (const ModeResult& m : report.modes)
        if (m.mode == Mode::Full && m.lodPixels > 0.0 && m.triangleBudget == 0 && m.frameBudgetMs == 0.0 &&
            m.sceneTag.empty())
            return &m;
    return nullptr;
}

void compareWithLodBaseline(BenchReport& report) {
    const ModeResult* baseline = lodBaseline(report);
    const double p50 = baseline ? baseline->frameMs.p50 : 0.0;
    for (ModeResult& m : report.modes)
        m.speedupLod =
            p50 > 0.0 && m.frameMs.p50 > 0.0 ? p50 / m.frameMs.p50 : std::numeric_limits<double>::quiet_NaN();
}

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

std::string_view toString(Mode mode) {
    switch (mode) {
        case Mode::Full: return "full";
        case Mode::Cells: return "cells";
        case Mode::CellsLayer: return "cells+layer";
        case Mode::Near: return "near";
        case Mode::Walls: return "walls";
        case Mode::Clusters: return "clusters";
    }
    return "?";
}

std::string transitionLabel(const ModeResult& m) {
    if (!m.transition) return "none";
    return std::string(app::toString(*m.transition)) + (m.paged ? " paged" : "") + (m.onDemand ? " on demand" : "");
}

std::string modeLabel(const ModeResult& m) {
    const std::string prefix = "walls " + std::string(walls::wallKindName(m.wallKind)) + " a=";
    std::string label =
        m.mode == Mode::Walls ? prefix + num(m.alphaDeg) + " " + transitionLabel(m) : std::string(toString(m.mode));
    if (m.lodPixels > 0.0) label += " lod " + num(m.lodPixels) + "px";
    if (m.triangleBudget > 0) label += " budget " + std::to_string(m.triangleBudget);
    if (m.frameBudgetMs > 0.0) label += " frame " + num(m.frameBudgetMs, 3) + "ms";
    if (!m.sceneTag.empty()) label += " [" + m.sceneTag + "]";
    return label;
}

std::string fixed(double v, int decimals) {
    if (std::isinf(v)) return v > 0.0 ? "inf" : "-inf";  // e.g. the PSNR of identical images
    if (std::isnan(v)) return "nan";
    std::ostringstream s;
    s.setf(std::ios::fixed);
    s.precision(decimals);
    s << v;
    return s.str();
}

// Column names and labels spell the FLIP threshold out.
static_assert(kFlipThreshold == 0.1, "rename flip_share_over_0.1 and the '% > 0.1' labels");

std::string csvHeader() {
    return "mode,alpha_deg,transition,frame_ms_p50,frame_ms_p95,frame_ms_p99,speedup,psnr_db,rmse,ssim,max_err_deg,"
           "max_err_px,triangles,draw_calls,textures,disk_mb,gpu_mb,cpu_ms_p50,cpu_ms_p95,cpu_ms_p99,gpu_ms_p50,"
           "gpu_ms_p95,gpu_ms_p99,texels,misses,mean_psnr_db,load_p99_p50,lod_px,triangle_budget,max_lod_err_px,"
           "mean_lod_tolerance_px,over_budget_frames,frame_budget_ms,worst_frame_psnr_db,p5_frame_psnr_db,flip_mean,"
           "flip_share_over_0.1,"
           "popping_peak,popping_rms,psnr_gain_db,flip_ratio,over_alpha,uploaded_mb_p50,uploaded_mb_p99,uploaded_mb_"
           "mean,"
           "p95_over_budget,floor_ms,first_frame_s,geometry_fallbacks,fallback_frames,fallbacks_until_frame,textures_"
           "baked,speedup_lod,scene,stereo_mean_arcmin,stereo_beyond_share,wall_kind,recommended";
}

std::string csvRow(const ModeResult& m, bool recommended) {
    const double values[] = {m.frameMs.p50,
                             m.frameMs.p95,
                             m.frameMs.p99,
                             m.speedup,
                             m.error.psnrDb,
                             m.error.rmse,
                             m.error.ssim,
                             m.maxErrDeg,
                             m.maxErrPx,
                             m.triangles,
                             m.drawCalls,
                             static_cast<double>(m.textures),
                             m.diskMB,
                             m.gpuMB,
                             m.cpuMs.p50,
                             m.cpuMs.p95,
                             m.cpuMs.p99,
                             m.gpuMs.p50,
                             m.gpuMs.p95,
                             m.gpuMs.p99,
                             m.texels,
                             static_cast<double>(m.misses),
                             m.error.meanPsnrDb,
                             m.loadRatio,
                             m.lodPixels,
                             static_cast<double>(m.triangleBudget),
                             m.maxLodErrPx,
                             m.meanLodTolerancePx,
                             static_cast<double>(m.overBudgetFrames),
                             m.frameBudgetMs,
                             m.error.worstFramePsnrDb,
                             m.error.p5FramePsnrDb,
                             m.error.flipMean,
                             m.error.flipOverThreshold,
                             m.error.poppingPeak,
                             m.error.poppingRms,
                             m.psnrGainDb,
                             m.flipRatio,
                             static_cast<double>(m.texturesOverAlpha),
                             m.uploadedMB.p50,
                             m.uploadedMB.p99,
                             m.uploadedMB.mean,
                             p95OverBudget(m),
                             medianFloorMs(m)};
    const OnDemandFigures f = m.onDemand.value_or(OnDemandFigures{});
    const double onDemand[] = {f.firstFrameSeconds, static_cast<double>(f.geometryFallbacks),
                               static_cast<double>(f.fallbackFrames), static_cast<double>(f.fallbacksUntilFrame),
                               static_cast<double>(f.texturesBaked)};
    std::string row = std::string(toString(m.mode)) + "," + num(m.alphaDeg) + "," + transitionLabel(m);
    for (double v : values) row += "," + num(v);
    for (double v : onDemand) row += "," + num(v);
    return row + "," + num(m.speedupLod) + "," + (m.sceneTag.empty() ? "bench" : m.sceneTag) + "," +
           stereoCsv(m.error) + "," + std::string(m.mode == Mode::Walls ? walls::wallKindName(m.wallKind) : "") +
           (recommended ? ",1" : ",0");
}

namespace {

// The image-error cells of a mode's bench.md row.
std::string errorCells(const ModeResult& m) {
    const ImageError& e = m.error;
    return num(e.psnrDb, 3) + " (" + num(e.worstFramePsnrDb, 3) + " / " + num(e.p5FramePsnrDb, 3) + ") | " +
           num(e.meanPsnrDb, 3) + " | " + num(e.rmse, 3) + " | " + num(e.ssim, 3) + " | " + num(e.flipMean, 3) + " / " +
           num(100.0 * e.flipOverThreshold, 3) + " | " + stereoCell(e) + " | " + num(e.poppingPeak, 3) + " / " +
           num(e.poppingRms, 3) + " | " +
           (m.mode == Mode::Walls ? num(m.psnrGainDb, 3) + " / " + num(m.flipRatio, 3) : std::string("-")) + " | ";
}

}  // namespace

std::string markdownReport(const BenchReport& report) {
    std::ostringstream md;
    for (const std::string& line : report.header) md << "- " << line << "\n";
    md << "\n| # | mode | frame ms p50 / p95 / p99 | p99/p50 | load p99/p50 | CPU ms p50 | GPU ms p50 | speed-up "
          "(against full geometry with LOD) | PSNR dB pooled (worst frame / p5 frame) | capped mean PSNR dB (not "
          "ranked) | RMSE | SSIM | FLIP mean / % > 0.1 "
          "| stereo err arcmin mean / % > 1 arcmin | popping peak / RMS | vs control: PSNR gain dB / FLIP ratio | max "
          "err deg / px "
          "| textures over alpha | LOD err px max (tolerance mean) | triangles | draw calls | textures | texels M | "
          "disk MB "
          "| GPU MB | uploaded MB per frame p50 / p99 |\n"
       << "| ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | "
          "---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: |\n";
    int index = 1;
    for (const ModeResult& m : report.modes) {
        const double ratio = m.frameMs.p50 > 0 ? m.frameMs.p99 / m.frameMs.p50 : 0.0;
        md << "| " << index++ << " | " << modeLabel(m) << " | " << num(m.frameMs.p50, 3) << " / "
           << num(m.frameMs.p95, 3) << " / " << num(m.frameMs.p99, 3) << " | " << num(ratio, 3) << " | "
           << num(m.loadRatio, 3) << " | " << num(m.cpuMs.p50, 3) << " | " << num(m.gpuMs.p50, 3) << " | "
           << num(m.speedup, 3) << (std::isnan(m.speedupLod) ? std::string() : " (" + num(m.speedupLod, 3) + ")")
           << " | " << errorCells(m) << num(m.maxErrDeg, 3) << " / " << num(m.maxErrPx, 3) << " | "
           << (m.mode == Mode::Walls ? std::to_string(m.texturesOverAlpha) : std::string("-")) << " | "
           << (m.lodPixels > 0.0 ? num(m.maxLodErrPx, 3) + " (" + num(m.meanLodTolerancePx, 3) + ")" : std::string("-"))
           << " | " << num(std::round(m.triangles), 7) << " | " << num(m.drawCalls, 3) << " | " << m.textures << " | "
           << num(m.texels / 1e6, 3) << " | " << num(m.diskMB, 3) << " | " << num(m.gpuMB, 3) << " | "
           << num(m.uploadedMB.p50, 3) << " / " << num(m.uploadedMB.p99, 3) << " |\n";
    }
    md << "\n- load p99/p50: p99/p50 of the triangles drawn per frame, how much the path's load alone varies "
          "(frame time grows with it on llvmpipe); PSNR pooled: from the mean squared error of all compared "
          "pixels of all frames (the figure every ranking uses), worst frame: the lowest PSNR of one compared frame "
          "(all screens), p5 frame: the 5th percentile of per-frame PSNR; capped mean: the mean of per-frame PSNRs, "
          "each capped at 58.9 dB (8-bit quantisation), which flatters and is not ranked by; FLIP: LDR-FLIP per "
          "image at its screen's pixels per degree from the frame's eye, mean over all compared pixels and the share "
          "of them above 0.1 (a colour difference near CIELAB's just-noticeable one; most pixels match exactly, so "
          "a percentile would read 0) "
          "(flip_worst_N.png: the map of mode N's worst image); stereo err (stereo displays only): per eye and pixel, "
          "|v(z) - v(z_full)| with v(z) = 2 atan(b / 2z) the vergence angle of the surface the pixel shows at distance "
          "z from that eye, b the viewer's eye separation (metrics/stereo_error.h), mean over all compared pixels "
          "in arc minutes and the share beyond 1 arcmin, a stereoacuity most viewers reach; popping: the "
          "frame-to-frame change of the error "
          "image against the reference's own change between consecutive compared frames, peak and RMS over frame "
          "pairs; vs control: pooled PSNR minus that of 'cells' (cell culling without textures) at the mode's level-of-"
          "detail tolerance (at full detail where the bench ran no cells at that tolerance), and FLIP mean over "
          "its; max err deg / px: the worst angular error of a drawn wall texture, in pixels at the pixels per "
          "degree of the screens showing the wall; LOD err px: the largest geometric error of a drawn level of detail "
          "in pixels on its screen (sampled "
          "Hausdorff distance to the full mesh, scenes/mesh_lod.h), and the mean pixel tolerance the frames used\n";
    for (std::size_t i = 0; i < report.modes.size(); ++i) {
        const ModeResult& m = report.modes[i];
        const FlipMap& map = m.flipWorst;
        if (map.image.width <= 0) continue;
        const std::string screen =
            map.screen >= 0 && map.screen < static_cast<int>(m.screens.size()) ? m.screens[map.screen].screen : "?";
        md << "- flip_worst_" << i + 1 << ".png: " << modeLabel(m) << ", frame " << map.frame << ", screen " << screen
           << ", eye " << map.eye << ", FLIP mean " << num(map.mean, 3) << "\n";
    }
    for (const std::string& line : figureLines(report)) md << "- " << line << "\n";
    md << "- " << recommendedLine(report) << "\n";
    return md.str();
}

std::string framesCsv(const BenchReport& report) {
    std::string out =
        "mode,frame,frame_ms,triangles,draw_calls,uploaded_mb,over_alpha,predicted_ms,predicted_frame_ms,"
        "floor_ms,geometry_fallbacks,textures_baked,kept_fallbacks\n";
    for (const ModeResult& m : report.modes)
        for (std::size_t i = 0; i < m.frames.size(); ++i)
            out += modeLabel(m) + "," + std::to_string(i) + "," + num(m.frames[i].frameMs, 6) + "," +
                   num(m.frames[i].triangles, 10) + "," + num(m.frames[i].drawCalls, 10) + "," +
                   num(m.frames[i].uploadedMB, 6) + "," + std::to_string(m.frames[i].texturesOverAlpha) + "," +
                   num(m.frames[i].predictedMs, 6) + "," + num(m.frames[i].predictedFrameMs, 6) + "," +
                   num(m.frames[i].floorMs, 6) + "," + std::to_string(m.frames[i].geometryFallbacks) + "," +
                   std::to_string(m.frames[i].texturesBaked) + "," + std::to_string(m.frames[i].keptFallbacks) + "\n";
    return out;
}

std::string comparedCsv(const BenchReport& report) {
    std::string out = "mode,frame,screen,eye,psnr_db,flip_mean\n";
    for (const ModeResult& m : report.modes)
        for (const ImageErrorRecord& r : m.comparedImages)
            out += modeLabel(m) + "," + std::to_string(r.frame) + "," +
                   (r.screen >= 0 && r.screen < static_cast<int>(m.screens.size()) ? m.screens[r.screen].screen : "?") +
                   "," + std::to_string(r.eye) + "," + num(r.psnrDb, 6) + "," + num(r.flipMean, 6) + "\n";
    return out;
}

std::vector<std::filesystem::path> writeReport(const std::filesystem::path& folder, const BenchReport& report) {
    std::filesystem::create_directories(folder);
    std::string csv = csvHeader() + "\n";
    for (std::size_t i = 0; i < report.modes.size(); ++i)
        csv += csvRow(report.modes[i], report.recommended == i) + "\n";
    const std::vector<std::filesystem::path> files = {folder / "bench.csv",        folder / "bench_screens.csv",
                                                      folder / "bench.md",         folder / "bench.png",
                                                      folder / "bench_frames.csv", folder / "bench_compared.csv"};
    writeText(files[0], csv);
    writeText(files[1], screensCsv(report));
    writeText(files[4], framesCsv(report));
    writeText(files[5], comparedCsv(report));
    writeText(files[2], "# cavewall bench\n\n" + markdownReport(report) +
                            "\n![pooled PSNR and FLIP mean (y) against median frame time (x) of every mode, named "
                            "\"#N label\" as the table; dashed: the Pareto front; ringed: the control and the best "
                            "alternative; diamond: the recommended walls mode](bench.png)\n");
    writePlot(files[3], tradeOffFigure(report));
    std::vector<std::filesystem::path> written = files;
    for (std::size_t i = 0; i < report.modes.size(); ++i) {
        const FlipMap& map = report.modes[i].flipWorst;
        if (map.image.width <= 0) continue;
        written.push_back(folder / ("flip_worst_" + std::to_string(i + 1) + ".png"));
        scenes::writeImage(written.back(), map.image);
        if (!report.saveWorst) continue;
        written.push_back(folder / ("worst_" + std::to_string(i + 1) + ".png"));
        scenes::writeImage(written.back(), map.test);
        written.push_back(folder / ("worst_" + std::to_string(i + 1) + "_full.png"));
        scenes::writeImage(written.back(), map.reference);
    }
    return written;
}

}  // namespace cavewall::bench
