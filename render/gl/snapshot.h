#pragma once
// Rendering a display to images in one call: the scene renderer, render targets and fold-out
// wired together for the render and demo commands and for tests.
//
// On a context with windows (one per screen, in screen order), each screen's image 0 is also
// shown in its window, and the image returned for it is what the window showed (read from its
// back buffer before the swap) whenever the window has the screen's resolution; otherwise the
// offscreen image is returned. Either way the pixels are the same up to the driver's blit. A
// screen with a projector correction shows its warped image, which then stands in `warped`.

#include "display/display.h"
#include "display/gl/context.h"
#include "display/gl/frame_images.h"
#include "display/gl/render_targets.h"
#include "display/gl/projector_pass.h"
#include "render/gl/scene_renderer.h"
#include "scenes/scene.h"

namespace cavewall::render::gl {

struct Snapshot {
    std::vector<scenes::ScreenImage> images;  // every output image (readFrame order), before correction
    // The corrected screens' images after their warp and blend pass (display/gl/projector_pass.h), in
    // the order of `images`, stems ending in "-warped"; empty when no screen is corrected.
    std::vector<scenes::ScreenImage> warped;
    scenes::Image foldout;
    FrameStats stats;  // gpuMs of this frame (not an earlier one)
};

class Snapshotter {
public:
    // Needs `context` current; keeps references to `display` and `context`, which must outlive
    // it. Throws Error as RenderTargets and SceneRenderer do.
    Snapshotter(const display::Display& display, const scenes::Scene& scene, display::gl::Context& context,
                RenderSettings settings = {});

    // Renders the frame for `head` (cave frame) with the CAVE at `worldFromCave` in the world.
    // `foldoutPixelsPerMetre` <= 0: the finest screen's density (display/foldout.h).
    Snapshot render(const display::HeadPose& head, const glm::dmat4& worldFromCave = glm::dmat4(1.0),
                    double foldoutPixelsPerMetre = 0.0);

private:
    void present(Snapshot& snapshot);

    const display::Display& _display;
    display::gl::Context& _context;
    display::gl::RenderTargets _targets;
    SceneRenderer _renderer;
    display::gl::ProjectorPasses _projectors;
};

}  // namespace cavewall::render::gl
