#pragma once
// Frame-time control: the triangle budget of the next frame from the time the last one took, so
// that frames take about a target time whatever the load and however fast the machine runs at
// the moment. Funkhouser & Séquin's feedback for time-critical rendering, applied to
// Maciel & Shirley's (1995) frame budget (which the renderer meets by raising its
// level-of-detail tolerance, walkthrough::gl::WalkthroughOptions): the budget is in time, the renderer's
// knob in triangles.
//
// Model: a frame of g triangles takes about a + b g milliseconds, a and b unknown and
// drifting (other tenants slow a shared machine down in phases). Each frame gives a cost per
// triangle u = m / g (fixed part included); the estimate û is the median of the last
// kWindow of them (display/timing.h: nearest rank, the lower middle of an even count), so
// one stalled frame (a page-in, a hiccup of the host) moves nothing while a slow phase is
// followed within a few frames. The next budget is g^(1 - gain) (T / û)^gain,
// within [g / 2, 2 g]. With gain 1 and the model exact this is T g / (a + b g), which converges
// on the g with a + b g = T (each step shrinks the error by a / T). A frame below its budget
// (light load) lets the next budget grow only from what it drew, so no credit builds up.
//
// An infeasible target (the renderer draws more than its budget: its coarsest levels of detail
// still exceed it) would otherwise leave every frame at whatever its view needs at the coarsest
// level, so the load follows the content. There the controller holds the load steady instead:
// it keeps a floor, raised to every such frame's triangles and decaying by kFloorDecay a frame,
// and never budgets below it. A view lighter at the coarsest level then draws finer levels up to
// the floor (frames as slow as the heaviest recent one, not slower); a heavier one raises it.
// The floor decays back to what the target allows when the target becomes feasible again.
//
// Pure and deterministic: the same times give the same budgets. Times in milliseconds.

#include <cstddef>

namespace cavewall::display {

class FrameTimeBudget {
public:
    // targetMs > 0; 0 < gain <= 1 (below 1 damps the reaction to a single slow frame).
    explicit FrameTimeBudget(double targetMs, double gain = 0.75);

    // The triangle budget for the next frame; 0 (no cap) until the first update.
    std::size_t budget() const { return _budget; }
    // The steady-load floor (0 while the target is feasible).
    double floor() const { return _floor; }
    double targetMs() const { return _target; }

    // After a frame: its wall-clock time and the triangles the budget capped (what the scene
    // renderer submitted). Non-finite or non-positive times are ignored.
    void update(double frameMs, std::size_t triangles);

private:
    static constexpr int kWindow = 5;
    static constexpr double kFloorDecay = 0.98;  // halves in about 35 frames
    double _target, _gain;
    double _floor = 0.0;
    std::size_t _budget = 0;
    double _costs[kWindow] = {};  // ms per triangle of the last frames, a ring
    int _count = 0, _next = 0;
};

}  // namespace cavewall::display
