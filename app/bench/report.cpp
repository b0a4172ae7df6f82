#include "app/bench/report.h"
#include "app/bench/report_text.h"

#include "config/error.h"
#include "config/json_reader.h"
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

namespace detail {

std::string num(double v, int digits) {
    if (std::isinf(v)) return v > 0 ? "inf" : "-inf";
    if (std::isnan(v)) return "nan";
    char buffer[40];
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, v);
    return buffer;
}

}  // namespace detail

using detail::num;

namespace {

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

// "inf" for the PSNR of identical images.
std::string fixed(double v, int decimals) { return config::formatFixed(v, decimals); }

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
    scenes::writeBytesAtomically(files[0], csv);
    scenes::writeBytesAtomically(files[1], screensCsv(report));
    scenes::writeBytesAtomically(files[4], framesCsv(report));
    scenes::writeBytesAtomically(files[5], comparedCsv(report));
    scenes::writeBytesAtomically(
        files[2], "# cavewall bench\n\n" + markdownReport(report) +
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
