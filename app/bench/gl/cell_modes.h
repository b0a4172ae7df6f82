#pragma once
// The cell modes of `cavewall bench` (app/bench/gl/driver.h): the control (the cells the walls
// draw as geometry, no textures), the control plus one textured layer, and the near limit, drawn
// with the frame selection of a walls setup's plan and no walls.

#include "app/bench/gl/modes.h"

#include <memory>
#include <vector>

namespace cavewall::bench::gl {

// What a cell mode draws besides the geometry of its cells (app/bench/gl/driver.h).
enum class CellDraw {
    Cells,       // the selection's geometry cells, nothing else (the control)
    CellsLayer,  // the same plus one textured full-screen layer per view through the wall pass:
                 // each view's own screen quad, a 512 x 512 MIP-mapped sRGB texture sampled as
                 // the walls' textures are, weight 0 (the image stays the control's; the cost
                 // is the layer's: the shader, the samples and the blend run for every pixel
                 // the layer covers, all but geometry nearer than the screen)
    Near,        // the viewer's cell only, plus its walls as bare quads (one 1x1 texture)
};

// One cell mode of a runCellModes call and where its frames go.
struct CellRun {
    CellDraw draw = CellDraw::Cells;
    ModeAccumulator* acc = nullptr;  // not null; its mode's lodPixels, the same for every run
};

// Draws cell modes with the selection of `setup`'s plan at one level-of-detail tolerance (no
// budget): one scene renderer and one set of render targets for all of them.
class CellModes {
public:
    // The context is current; keeps references to `c` and `setup`, which must outlive it.
    CellModes(const ModeContext& c, const walls::WallSetup& setup, double lodPixels);
    ~CellModes();
    CellModes(const CellModes&) = delete;
    CellModes& operator=(const CellModes&) = delete;

    // Draws the path's first three frames as every run draws them, untimed.
    void warmUp(const std::vector<CellRun>& runs);
    // Draws path frame `in` as every run draws it, in turn: each run's cost into its
    // accumulator and, when in.readImages, its images (and depths where readsDepth) compared
    // with the reference of the same frame. Every run's mode has the tolerance of the drawer.
    void drawFrame(const walkthrough::FrameInput& in, const std::vector<CellRun>& runs,
                   const ReferenceImages& reference);

private:
    struct State;
    std::unique_ptr<State> _s;
    FrameCost draw(const walkthrough::FrameInput& in, CellDraw kind);
};

// Runs cell modes with the selection of `setup`'s plan, at the modes' level-of-detail tolerance
// (bench::ModeResult::lodPixels, the same for all; no budget), interleaved: every path frame is
// drawn by each run in turn, so that their times share the machine's load of the same seconds.
void runCellModes(const ModeContext& c, const walls::WallSetup& setup, const std::vector<CellRun>& runs,
                  const ReferenceImages& reference);

}  // namespace cavewall::bench::gl
