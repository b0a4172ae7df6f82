#include "app/gl/run_output.h"

#include "config/error.h"
#include "scenes/file_write.h"
#include "scenes/image_io.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cerrno>
#include <cstring>
#include <string>
#include <unistd.h>

namespace cavewall::app::gl {

namespace {

std::string exact(double v) {
    char buffer[32];
    const auto end = std::to_chars(buffer, buffer + sizeof buffer, v).ptr;
    return std::string(buffer, end);
}

std::FILE* openCsv(const std::filesystem::path& file, const char* header) {
    std::FILE* f = std::fopen(file.c_str(), "w");
    if (!f) throw Error(file.string() + ": cannot write (" + std::strerror(errno) + ")");
    std::fputs(header, f);
    return f;
}

}  // namespace

RunOutput::RunOutput(std::filesystem::path folder, const scenes::SceneDescription& description,
                     const display::Display& display)
    : _folder(std::move(folder)), _description(description), _display(display) {
    std::error_code ec;
    std::filesystem::create_directories(_folder, ec);
    if (ec) throw Error("--out: cannot create '" + _folder.string() + "' (" + ec.message() + ")");
    _frames = openCsv(
        _folder / "frames.csv",
        "frame,t,head_x,head_y,head_z,world_x,world_y,world_z,cell,zone,frame_ms,cpu_ms,gpu_ms,"
        "triangles,draw_calls,textures_resident,page_ins,misses,max_err_deg,max_err_px,fallbacks,sync_ms,warp_"
        "fallbacks,"
        "lod_px,lod_err_px,lod_over_budget,geometry_triangles,over_alpha,geometry_resident_mb,geometry_page_ins,"
        "geometry_misses,geometry_kept,geometry_forced,uploaded_mb,cluster_objects,cluster_textured,"
        "cluster_average,cluster_predicted_ms,cluster_budget_ms,cluster_fades,geometry_fallbacks,"
        "textures_baked,textures_baked_now,textures_to_bake,baker_busy,cluster_selected_ms,"
        "cluster_cheapest_ms,cluster_target_ms,cluster_predicted_frame_ms,cluster_floor_ms,view_yaw_deg,"
        "view_pitch_deg\n");
    _walls = openCsv(_folder / "walls.csv", "frame,wall,textures,geometry_weight,fallback,beyond,err_deg,over_alpha\n");
}

RunOutput::~RunOutput() {
    if (_frames) std::fclose(_frames);
    if (_walls) std::fclose(_walls);
}

void RunOutput::close() {
    for (auto [file, name] : {std::pair{&_frames, "frames.csv"}, std::pair{&_walls, "walls.csv"}}) {
        if (!*file) continue;
        int error = std::fflush(*file) == 0 && !std::ferror(*file) ? 0 : errno;
        if (!error && ::fsync(::fileno(*file)) != 0) error = errno;
        if (std::fclose(*file) != 0 && !error) error = errno;
        *file = nullptr;
        if (error) throw Error((_folder / name).string() + ": cannot write (" + scenes::writeErrorText(error) + ")");
    }
}

void RunOutput::writeFrame(long frame, double t, glm::dvec3 head, const walkthrough::FrameResult& r, double syncMs,
                           glm::dvec3 viewWorld) {
    viewWorld = glm::normalize(viewWorld);
    const double yawDeg = glm::degrees(std::atan2(-viewWorld.x, -viewWorld.z));
    const double pitchDeg = glm::degrees(std::asin(std::clamp(viewWorld.y, -1.0, 1.0)));
    const glm::dvec3& w = r.eyeWorld;
    const std::string cell =
        r.cell >= 0 && r.cell < static_cast<int>(_description.cells.size()) ? _description.cells[r.cell].name : "-";
    int fallbacks = 0;
    for (const walkthrough::WallState& s : r.walls) fallbacks += s.fallback ? 1 : 0;
    std::fprintf(
        _frames,
        "%ld,%s,%s,%s,%s,%s,%s,%s,%s,%d,%.3f,%.3f,%.3f,%zu,%d,%d,%ld,%ld,%.4f,%.2f,%d,%.3f,%d,%.3f,%.3f,%d,%zu,%d,%.3f,"
        "%ld,%ld,%d,%d,%.3f,%d,%d,%d,%.4f,%.4f,%d,%d,%d,%d,%d,%d,%.4f,%.4f,%.3f,%.3f,%.3f,%.4f,%.4f\n",
        frame, exact(t).c_str(), exact(head.x).c_str(), exact(head.y).c_str(), exact(head.z).c_str(),
        exact(w.x).c_str(), exact(w.y).c_str(), exact(w.z).c_str(), cell.c_str(), r.zone, r.frameMs, r.cpuMs, r.gpuMs,
        r.stats.triangles, r.stats.drawCalls, r.pager.resident, r.pager.pageIns, r.pager.misses, r.maxErrorDeg,
        r.maxErrorPixels, fallbacks, syncMs, r.warpFallbacks, r.lodTolerancePx, r.lodErrorPx, r.lodOverBudget ? 1 : 0,
        r.geometryTriangles, r.texturesOverAlpha, r.geometry.residentMB, r.geometry.pageIns, r.geometry.misses,
        r.geometryMisses, r.geometryForced, static_cast<double>(r.uploadedBytes) / 1e6, r.clusterObjects,
        r.clusterTextured, r.clusterAverage, r.clusterPredictedMs, r.clusterBudgetMs, r.clusterFades,
        r.geometryFallbacks, r.texturesBaked, r.texturesBakedNow, r.texturesToBake, r.bakerBusy ? 1 : 0,
        r.clusterSelectedMs, r.clusterCheapestMs, r.clusterTargetMs, r.clusterPredictedFrameMs, r.clusterFloorMs,
        yawDeg, pitchDeg);
    for (const walkthrough::WallState& s : r.walls) {
        std::string textures;
        for (const auto& [id, weight] : s.textures)
            textures += (textures.empty() ? "" : ";") + std::to_string(id) + ":" + exact(weight);
        const std::string name = s.wall < static_cast<int>(_description.walls.size()) ? _description.walls[s.wall].name
                                                                                      : std::to_string(s.wall);
        std::fprintf(_walls, "%ld,%s,%s,%s,%d,%d,%.4f,%d\n", frame, name.c_str(), textures.c_str(),
                     exact(s.geometryWeight).c_str(), s.fallback ? 1 : 0, s.beyond ? 1 : 0, s.errorDeg,
                     s.texturesOverAlpha);
    }
    std::fflush(_frames);
    std::fflush(_walls);
    if (std::ferror(_frames) || std::ferror(_walls))
        throw Error(_folder.string() + ": writing the CSV files failed (" + scenes::writeErrorText(errno) + ")");
}

std::filesystem::path RunOutput::saveImages(long frame, const std::vector<scenes::ScreenImage>& images,
                                            const std::vector<scenes::ScreenImage>& warped) {
    char name[16];
    std::snprintf(name, sizeof name, "%05ld", frame);
    const std::filesystem::path folder = _folder / "frames" / name;
    std::filesystem::create_directories(folder);
    const auto files = display::gl::writeFrame(folder, images, display::gl::foldoutOf(_display, images));
    for (const scenes::ScreenImage& w : warped) scenes::writeImage(folder / (w.stem + ".png"), w.pixels);
    return files.back();
}

}  // namespace cavewall::app::gl
