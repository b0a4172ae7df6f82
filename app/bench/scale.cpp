#include "app/bench/scale.h"

#include "config/error.h"
#include "config/json_depth.h"
#include "config/json_reader.h"
#include "app/bench/gnuplot.h"
#include "app/bench/recommend.h"
#include "app/bench/report.h"
#include "scenes/file_write.h"
#include "scenes/generate.h"
#include "scenes/image_io.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <map>
#include <nlohmann/json.hpp>

namespace cavewall::bench {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

double millions(std::size_t triangles) { return static_cast<double>(triangles) / 1e6; }

std::vector<const ScaleRow*> rowsOf(const ScaleReport& report, ScaleMode mode) {
    std::vector<const ScaleRow*> rows;
    for (const ScaleRow& r : report.rows)
        if (r.mode == mode) rows.push_back(&r);
    std::sort(rows.begin(), rows.end(), [](auto a, auto b) { return a->triangles < b->triangles; });
    return rows;
}

// The modes that page geometry by cell (their paged peak is reported).
bool pagesGeometry(ScaleMode mode) {
    return mode == ScaleMode::Walls || mode == ScaleMode::WallsBudget || mode == ScaleMode::DepthWalls ||
           mode == ScaleMode::Cells;
}

// Modes a run may leave out (their slopes are not printed then).
bool mayBeLeftOut(ScaleMode mode) {
    return mode == ScaleMode::WallsBudget || mode == ScaleMode::DepthWalls || mode == ScaleMode::Cells ||
           mode == ScaleMode::FullLod;
}

// The stereo error's CSV cells: mean arc minutes and the share of pixels beyond 1 arcmin; nan
// when not measured (mono, or full geometry, the reference).
std::string stereoCsv(const ScaleRow& r) {
    if (!r.stereoMeasured) return "nan,nan";
    return fixed(r.stereo.meanArcmin(), 5) + "," + fixed(r.stereo.shareBeyond(), 5);
}

// The stereo error's scale.md cell: "mean (% beyond 1')"; "–" when not measured.
std::string stereoCell(const ScaleRow& r) {
    if (!r.stereoMeasured) return "–";
    return fixed(r.stereo.meanArcmin(), 4) + " (" + fixed(100.0 * r.stereo.shareBeyond(), 2) + " %)";
}

}  // namespace

std::string_view toString(ScaleMode mode) {
    switch (mode) {
        case ScaleMode::Full: return "full";
        case ScaleMode::FullLod: return "full-lod";
        case ScaleMode::Near: return "near";
        case ScaleMode::Walls: return "walls";
        case ScaleMode::WallsBudget: return "walls-budget";
        case ScaleMode::DepthWalls: return "walls-depth";
        case ScaleMode::Cells: return "cells";
    }
    return "?";
}

double msPerMillionTriangles(const ScaleReport& report, ScaleMode mode) {
    const std::vector<const ScaleRow*> rows = rowsOf(report, mode);
    if (rows.size() < 2) return kNaN;
    double mx = 0.0, my = 0.0;
    for (const ScaleRow* r : rows) {
        mx += millions(r->triangles);
        my += r->frameMs.p50;
    }
    mx /= static_cast<double>(rows.size());
    my /= static_cast<double>(rows.size());
    double sxy = 0.0, sxx = 0.0;
    for (const ScaleRow* r : rows) {
        const double dx = millions(r->triangles) - mx;
        sxy += dx * (r->frameMs.p50 - my);
        sxx += dx * dx;
    }
    return sxx > 0.0 ? sxy / sxx : kNaN;
}

double growth(const ScaleReport& report, ScaleMode mode) {
    const std::vector<const ScaleRow*> rows = rowsOf(report, mode);
    if (rows.size() < 2 || !(rows.front()->frameMs.p50 > 0.0)) return kNaN;
    return rows.back()->frameMs.p50 / rows.front()->frameMs.p50;
}

std::string scaleCsv(const ScaleReport& report) {
    std::string out =
        "target_triangles,triangles,cells,mode,triangle_budget,frame_ms_p50,frame_ms_p95,frame_ms_p99,"
        "triangles_per_frame,"
        "resident_mb,paged_peak_mb,whole_model_mb,largest_three_cells_mb,load_s,first_frame_s,"
        "geometry_misses,geometry_page_ins,textures_over_alpha,compared_frames,psnr_db,"
        "worst_frame_psnr_db,flip_mean,worst_image_flip,stereo_arcmin,stereo_beyond_1arcmin\n";
    for (const ScaleRow& r : report.rows)
        out += std::to_string(r.targetTriangles) + "," + std::to_string(r.triangles) + "," + std::to_string(r.cells) +
               "," + std::string(toString(r.mode)) + "," + std::to_string(r.triangleBudget) + "," +
               fixed(r.frameMs.p50, 3) + "," + fixed(r.frameMs.p95, 3) + "," + fixed(r.frameMs.p99, 3) + "," +
               fixed(r.trianglesPerFrame, 0) + "," + fixed(r.residentMB, 3) + "," + fixed(r.pagedPeakMB, 3) + "," +
               fixed(r.wholeModelMB, 3) + "," + fixed(r.largestThreeCellsMB, 3) + "," + fixed(r.loadSeconds, 3) + "," +
               fixed(r.firstFrameSeconds, 3) + "," + std::to_string(r.geometryMisses) + "," +
               std::to_string(r.geometryPageIns) + "," + std::to_string(r.texturesOverAlpha) + "," +
               std::to_string(r.comparedFrames) + "," + fixed(r.psnrDb, 3) + "," + fixed(r.worstFramePsnrDb, 3) + "," +
               fixed(r.flipMean, 5) + "," + fixed(r.worstImageFlip, 5) + "," + stereoCsv(r) + "\n";
    return out;
}

std::string scaleMarkdown(const ScaleReport& report) {
    std::string out;
    for (const std::string& line : report.header) out += "- " + line + "\n";
    out +=
        "\n| triangles | cells | mode | frame ms p50 | p95 | triangles/frame | resident MB | paged peak MB | "
        "whole model MB | largest 3 cells MB | load s | first frame s | geometry misses | over alpha | "
        "PSNR dB pooled (worst frame) | FLIP mean | worst image FLIP | stereo arcmin (% > 1') |\n"
        "| ---: | ---: | --- | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | ---: | "
        "---: | ---: | ---: |\n";
    for (const ScaleRow& r : report.rows)
        out +=
            "| " + fixed(millions(r.triangles), 2) + " M | " + std::to_string(r.cells) + " | " +
            std::string(toString(r.mode)) + " | " + fixed(r.frameMs.p50, 2) + " | " + fixed(r.frameMs.p95, 2) + " | " +
            fixed(r.trianglesPerFrame, 0) + " | " + fixed(r.residentMB, 2) + " | " +
            (pagesGeometry(r.mode) ? fixed(r.pagedPeakMB, 2) : std::string("–")) + " | " + fixed(r.wholeModelMB, 2) +
            " | " + fixed(r.largestThreeCellsMB, 2) + " | " + fixed(r.loadSeconds, 2) + " | " +
            fixed(r.firstFrameSeconds, 2) + " | " + std::to_string(r.geometryMisses) + " | " +
            std::to_string(r.texturesOverAlpha) + " | " +
            (r.comparedFrames > 0 ? fixed(r.psnrDb, 1) + " (" + fixed(r.worstFramePsnrDb, 1) + ")" : std::string("–")) +
            " | " + (r.comparedFrames > 0 ? fixed(r.flipMean, 4) : std::string("–")) + " | " +
            (r.comparedFrames > 0 ? fixed(r.worstImageFlip, 4) : std::string("–")) + " | " + stereoCell(r) + " |\n";
    out +=
        "\nSlopes (least squares of the median frame ms against millions of triangles) and growth (median at the "
        "largest size over the smallest):\n\n";
    for (ScaleMode m : kScaleModes) {
        if (mayBeLeftOut(m) && rowsOf(report, m).empty()) continue;  // not run
        const double slope = msPerMillionTriangles(report, m);
        out += "- " + std::string(toString(m)) + ": " +
               (std::isnan(slope) ? std::string("no slope (it needs two sizes or more)")
                                  : fixed(slope, 3) + " ms per M triangles, " + fixed(growth(report, m), 2) + "x") +
               "\n";
    }
    out +=
        "\nWalls against full geometry at each size (median frame ms over median frame ms; in parentheses against "
        "full geometry with levels of detail at the walls' tolerance, when run; and the walls' image error):\n\n";
    for (ScaleMode m : {ScaleMode::Walls, ScaleMode::WallsBudget, ScaleMode::DepthWalls})
        for (const ScaleRow* w : rowsOf(report, m))
            for (const ScaleRow* f : rowsOf(report, ScaleMode::Full)) {
                if (f->targetTriangles != w->targetTriangles || !(w->frameMs.p50 > 0.0)) continue;
                const std::string budget =
                    m == ScaleMode::WallsBudget ? " (" + std::to_string(w->triangleBudget) + " triangles a frame)" : "";
                const std::string error = w->comparedFrames > 0
                                              ? "pooled PSNR " + fixed(w->psnrDb, 1) + " dB (worst frame " +
                                                    fixed(w->worstFramePsnrDb, 1) + " dB), FLIP mean " +
                                                    fixed(w->flipMean, 4) + " over " +
                                                    std::to_string(w->comparedFrames) + " compared frames"
                                              : std::string("image error not compared");
                std::string lod;  // against the alternative a user would pick
                for (const ScaleRow* l : rowsOf(report, ScaleMode::FullLod))
                    if (l->targetTriangles == w->targetTriangles)
                        lod = " (" + fixed(l->frameMs.p50 / w->frameMs.p50, 2) +
                              "x against full geometry with levels of detail)";
                out += "- " + fixed(millions(w->triangles), 2) + " M triangles, " + std::string(toString(m)) + budget +
                       ": speed-up " + fixed(f->frameMs.p50 / w->frameMs.p50, 2) + "x" + lod + ", " + error + ", " +
                       std::to_string(w->texturesOverAlpha) + " textures over alpha\n";
            }
    if (!rowsOf(report, ScaleMode::Cells).empty()) {
        out +=
            "\nAgainst the control, cells without textures (the walls' geometry cells, no texture): what the "
            "textures buy (pooled PSNR gain, FLIP mean over the control's):\n\n";
        for (const ScaleRow* c : rowsOf(report, ScaleMode::Cells)) {
            if (c->comparedFrames <= 0) continue;
            std::string line = "- " + fixed(millions(c->triangles), 2) + " M triangles: cells " + fixed(c->psnrDb, 1) +
                               " dB (worst frame " + fixed(c->worstFramePsnrDb, 1) + " dB), FLIP mean " +
                               fixed(c->flipMean, 4);
            for (ScaleMode m : {ScaleMode::Walls, ScaleMode::WallsBudget, ScaleMode::DepthWalls})
                for (const ScaleRow* w : rowsOf(report, m))
                    if (w->targetTriangles == c->targetTriangles && w->comparedFrames > 0)
                        line += "; " + std::string(toString(m)) + " " + (w->psnrDb >= c->psnrDb ? "+" : "") +
                                fixed(w->psnrDb - c->psnrDb, 1) + " dB, FLIP " +
                                (c->flipMean > 0.0 ? fixed(w->flipMean / c->flipMean, 2) + "x" : std::string("–"));
            out += line + "\n";
        }
    }
    if (!rowsOf(report, ScaleMode::DepthWalls).empty()) {
        out +=
            "\nDepth walls against flat walls, drawn frame by frame in turn in this run (median frame ms over "
            "median frame ms):\n\n";
        for (const ScaleRow* d : rowsOf(report, ScaleMode::DepthWalls))
            for (const ScaleRow* f : rowsOf(report, ScaleMode::Walls))
                if (f->targetTriangles == d->targetTriangles && f->frameMs.p50 > 0.0)
                    out += "- " + fixed(millions(d->triangles), 2) + " M triangles: depth / flat " +
                           fixed(d->frameMs.p50 / f->frameMs.p50, 3) + " (" + fixed(d->frameMs.p50, 2) + " / " +
                           fixed(f->frameMs.p50, 2) + " ms)\n";
    }
    out += "\nThe recommended walls mode at each size (app/bench/recommend.h, docs/benchmarking.md):\n\n";
    for (const std::string& line : scaleRecommendedLines(report)) out += "- " + line + "\n";
    return out;
}

namespace {

// One mode's legend entry in the scale plots.
std::string seriesName(ScaleMode mode) {
    const std::string name(toString(mode));
    switch (mode) {
        case ScaleMode::Full: return name + ": full geometry";
        case ScaleMode::FullLod: return name + ": full geometry with levels of detail";
        case ScaleMode::Near: return name + ": viewer's cell and structure (the limit)";
        case ScaleMode::Cells: return name + ": cells without textures (the control)";
        case ScaleMode::Walls: return name + ": flat walls (textured virtual walls)";
        case ScaleMode::WallsBudget: return name + ": flat walls under a triangle budget";
        case ScaleMode::DepthWalls: return name + ": depth walls";
    }
    return name;
}

// One line per mode that ran, over the plant sizes; rows whose figure is not finite are left out.
Figure scaleFigure(const ScaleReport& report, const std::string& title, const PlotAxis& y,
                   double (*value)(const ScaleRow&)) {
    PlotPanel panel;
    panel.title = title;
    panel.x = {"triangles in the model", "millions", true};
    panel.y = y;
    for (ScaleMode m : kScaleModes) {
        PlotSeries s{.name = seriesName(m), .style = SeriesStyle::Line};
        for (const ScaleRow* r : rowsOf(report, m))
            if (std::isfinite(value(*r))) s.points.push_back({millions(r->triangles), value(*r)});
        if (!s.points.empty()) panel.series.push_back(std::move(s));
    }
    Figure figure;
    figure.panels = {std::move(panel)};
    figure.width = 900;
    figure.height = 640;
    return figure;
}

}  // namespace

std::vector<std::filesystem::path> writeScaleReport(const std::filesystem::path& folder, const ScaleReport& report) {
    std::filesystem::create_directories(folder);
    const std::vector<std::filesystem::path> files = {folder / "scale.csv", folder / "scale.md",
                                                      folder / "scale_ms.png", folder / "scale_mb.png",
                                                      folder / "scale_load.png"};
    scenes::writeBytesAtomically(files[0], scaleCsv(report));
    scenes::writeBytesAtomically(
        files[1], "# cavewall bench --scale\n\n" + scaleMarkdown(report) +
                      "\nPlots against millions of triangles (x), one named line per mode that ran: "
                      "median frame ms (scale_ms.png), resident geometry MB (scale_mb.png), seconds from the "
                      "loaded scene to the first frame plus the load (scale_load.png).\n\n"
                      "![frame ms](scale_ms.png) ![resident MB](scale_mb.png) ![first frame s](scale_load.png)\n");
    writePlot(files[2], scaleFigure(report, "Frame time against model size", {"median frame time, all screens", "ms"},
                                    [](const ScaleRow& r) { return r.frameMs.p50; }));
    writePlot(files[3], scaleFigure(report, "GPU memory for geometry against model size",
                                    {"resident geometry, the most at once", "MB"},
                                    [](const ScaleRow& r) { return r.residentMB; }));
    writePlot(files[4],
              scaleFigure(report, "Time to the first frame against model size", {"load plus first frame", "s"},
                          [](const ScaleRow& r) { return r.loadSeconds + r.firstFrameSeconds; }));
    return files;
}

namespace {

// One --scale entry: decimal digits (one '.' at most), then k or M in either case. Hexadecimal,
// exponents, signs and spaces, which strtod would read, are refused: the help promises none.
std::size_t scaleEntry(const std::string& entry, std::size_t index) {
    const std::string where = "bench: --scale: entry " + std::to_string(index) + " '" + entry + "': ";
    std::string digits = entry;
    double factor = 1.0;
    if (!digits.empty() && (digits.back() == 'M' || digits.back() == 'm')) {
        factor = 1e6;
        digits.pop_back();
    } else if (!digits.empty() && (digits.back() == 'k' || digits.back() == 'K')) {
        factor = 1e3;
        digits.pop_back();
    }
    const bool decimal = digits.find_first_not_of("0123456789.") == std::string::npos &&
                         std::count(digits.begin(), digits.end(), '.') <= 1 &&
                         digits.find_first_of("0123456789") != std::string::npos;
    const double value = decimal ? std::strtod(digits.c_str(), nullptr) * factor : kNaN;
    if (!(value >= 0.5))  // rounds to at least one triangle
        throw Error(where +
                    "expected a triangle count such as 2M, 500k or 8000000 (decimal digits, then k or M; at least 1)");
    const auto triangles = static_cast<std::size_t>(std::llround(std::min(value, 1e18)));
    if (triangles > scenes::kPlantMaxTriangles)
        throw Error(where + "expected at most " + std::to_string(scenes::kPlantMaxTriangles) +
                    " triangles (128M, the largest plant the generator makes), got " +
                    (value < 1e18 ? std::to_string(triangles) : std::string("more")));
    return triangles;
}

}  // namespace

void writePlantStamp(const std::filesystem::path& folder, std::size_t target, std::size_t triangles) {
    const nlohmann::json stamp{{"generator", "cavewall bench --scale"}, {"target", target}, {"triangles", triangles}};
    scenes::writeBytesAtomically(folder / kPlantStamp, stamp.dump(1) + "\n");
}

void checkPlantFolder(const std::filesystem::path& folder, std::size_t target, std::size_t triangles,
                      const std::function<std::size_t()>& generatedTriangles) {
    const std::filesystem::path file = folder / kPlantStamp;
    const std::string where = "bench --scale: " + folder.string() + ": ";
    const std::string fix = "; remove the folder to generate the plant again, or give another --data";
    std::size_t stampedTarget = target, expected = 0;
    if (std::filesystem::exists(file)) {
        try {
            const std::string text = config::readTextFile(file);
            config::checkJsonDepth(text, file.string());
            const nlohmann::json stamp = nlohmann::json::parse(text);
            stampedTarget = stamp.at("target").get<std::size_t>();
            expected = stamp.at("triangles").get<std::size_t>();
        } catch (const std::exception& e) {
            throw Error(where + "expected a readable " + kPlantStamp + ", got " + e.what() + fix);
        }
    } else {
        expected = generatedTriangles();
    }
    if (stampedTarget != target)
        throw Error(where + "expected the plant generated for " + std::to_string(target) + " triangles, got one for " +
                    std::to_string(stampedTarget) + " (" + kPlantStamp + ")" + fix);
    if (triangles != expected)
        throw Error(where + "expected the plant generated for " + std::to_string(target) + " triangles (" +
                    std::to_string(expected) + " drawn), got a model of " + std::to_string(triangles) +
                    " drawn triangles" + fix);
    if (!std::filesystem::exists(file)) writePlantStamp(folder, target, triangles);
}

std::vector<std::size_t> parseScaleList(const std::string& text) {
    std::vector<std::size_t> out;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = std::min(text.find(',', start), text.size());
        out.push_back(scaleEntry(text.substr(start, end - start), out.size() + 1));
        start = end + 1;
    }
    return out;
}

std::vector<glm::dvec3> pathPrefix(const std::vector<glm::dvec3>& points, double metres) {
    std::vector<glm::dvec3> out;
    if (points.empty()) return out;
    out.push_back(points.front());
    double left = metres;
    for (std::size_t i = 1; i < points.size(); ++i) {
        const double step = glm::length(points[i] - points[i - 1]);
        if (step >= left) {
            if (left > 0.0) out.push_back(points[i - 1] + (points[i] - points[i - 1]) * (left / step));
            return out;
        }
        left -= step;
        out.push_back(points[i]);
    }
    return out;
}

}  // namespace cavewall::bench
