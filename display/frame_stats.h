#pragma once
// What drawing a view and a frame cost and submitted: plain counters filled by the GL passes
// (render/gl/scene_renderer.h, walls/gl/) and reported by the walkthrough (walkthrough/frame_types.h).

#include <cstddef>
#include <vector>

namespace cavewall::display {

// What one view cost and submitted.
struct ViewStats {
    int objectsDrawn = 0;       // objects submitted (after filter and culling)
    int drawCalls = 0;          // GL draw commands issued (one multi-draw counts once)
    std::size_t triangles = 0;  // triangles submitted
    // Milliseconds of wall-clock time on the calling thread (the "CPU side"; drivers that shade
    // vertices on that thread, like llvmpipe, make submission include vertex work):
    double cullMs = 0.0;  // filtering and frustum culling
    double cpuMs = 0.0;   // the whole view: state, culling, uploads, command submission
};

// What a frame cost: the sum over its views, plus GPU time.
struct FrameStats {
    int drawCalls = 0;
    std::size_t triangles = 0;
    int objectsDrawn = 0;
    int views = 0;
    double cullMs = 0.0;  // summed over views (wall-clock ms, as ViewStats)
    double cpuMs = 0.0;   // render() until every command was submitted (wall-clock ms)
    // GL_TIME_ELAPSED of the most recent frame whose timer result is available without waiting
    // (a ring of queries; usually one or two frames old); -1 until one is available.
    double gpuMs = -1.0;
    std::vector<ViewStats> perView;  // in the order the views were drawn

    void add(const ViewStats& view);  // adds a view's numbers to the totals and perView
};

}  // namespace cavewall::display
