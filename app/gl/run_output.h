#pragma once
// The files of a `cavewall run`:
//   frames.csv  one row per frame: frame, t, head_x, head_y, head_z, world_x, world_y, world_z,
//               cell, zone, frame_ms, cpu_ms, gpu_ms, triangles, draw_calls, textures_resident,
//               page_ins, misses, max_err_deg, max_err_px, fallbacks, sync_ms, warp_fallbacks,
//               lod_px, lod_err_px, lod_over_budget, geometry_triangles, over_alpha
//               (head in the cave frame and world = cyclopean eye in the scene, metres; cell is
//               the cell's name or "-" outside every cell; zone -1 for none; misses and
//               page_ins are running totals; fallbacks = walls drawn from a previous texture or
//               as geometry because a wanted texture was not resident; sync_ms = cluster
//               mode's slowest rank's wait for the frame broadcast and the swap lock;
//               max_err_deg the exact error of the worst texture drawn; over_alpha the textures
//               drawn whose exact error exceeds the plan's alpha, 0 while the bound holds),
//               ..., geometry_fallbacks (walls drawn as geometry this frame for want of a
//               resident texture), textures_baked (baked by this run's background baker and
//               handed to the pager, running total), textures_baked_now (this frame),
//               textures_to_bake (still missing; all three 0 without --bake-on-demand),
//               baker_busy (1 when a background bake ran during some of the frame), ...,
//               view_yaw_deg, view_pitch_deg (where the head looks in the world: yaw about +Y,
//               0 looking down -Z and positive turning left; pitch positive looking up)
//   walls.csv   one row per frame and wall bounding the viewer's cell or beyond a neighbour
//               drawn as geometry: frame, wall (name), textures ("id:weight" joined by ';'),
//               geometry_weight, fallback (0/1), beyond (0/1), err_deg (the exact error of its
//               worst texture drawn with weight > 0), over_alpha (its textures over alpha)
//   frames/<frame, 5 digits>/<stem>.png and foldout.png for every saved frame.
// Poses are written in the shortest form that reads back to the same double, so replays can be
// compared exactly.

#include "display/display.h"
#include "display/gl/frame_images.h"
#include "scenes/scene_description.h"
#include "walkthrough/gl/walkthrough.h"

#include <cstdio>
#include <filesystem>
#include <vector>

namespace cavewall::app::gl {

class RunOutput {
public:
    // Creates `folder` and both CSV files; throws Error when they cannot be written.
    // Keeps references to `description` and `display`.
    RunOutput(std::filesystem::path folder, const scenes::SceneDescription& description,
              const display::Display& display);
    ~RunOutput();
    RunOutput(const RunOutput&) = delete;
    RunOutput& operator=(const RunOutput&) = delete;

    // `syncMs`: cluster mode's wait for the frame broadcast and the swap lock (0 otherwise);
    // `viewWorld`: the head's forward direction in the world (any length > 0). Both CSV files
    // are flushed after the frame, so a reader polling them sees whole rows.
    void writeFrame(long frame, double t, glm::dvec3 head, const walkthrough::FrameResult& result, double syncMs = 0.0,
                    glm::dvec3 viewWorld = {0.0, 0.0, -1.0});
    // Writes the frame's images, the fold-out and the projector-corrected images (`warped`,
    // walkthrough::FrameResult::warpedImages); returns the fold-out's path.
    std::filesystem::path saveImages(long frame, const std::vector<scenes::ScreenImage>& images,
                                     const std::vector<scenes::ScreenImage>& warped = {});
    // Flushes, syncs and closes both CSV files; throws Error with the system's reason (a full
    // disk says so) when any of it did not reach the disk. Call once after the last frame.
    void close();

private:
    std::filesystem::path _folder;
    const scenes::SceneDescription& _description;
    const display::Display& _display;
    std::FILE* _frames = nullptr;
    std::FILE* _walls = nullptr;
};

}  // namespace cavewall::app::gl
