#pragma once
// The one per-view frame loop: every caller that draws a frame view by view (the scene
// renderer's render(), the walkthrough, the bench's cell modes) plugs its passes into it.

#include "display/display.h"
#include "display/gl/render_targets.h"
#include "render/gl/scene_renderer.h"

#include <cstddef>
#include <functional>
#include <vector>

namespace cavewall::render::gl {

// What one view draws: everything a caller does with the view's target bound (scene geometry,
// then its own passes), returning what it submitted. ViewStats::cpuMs is set by forEachView.
using ViewPass = std::function<ViewStats(const display::ScreenView&)>;

// For every view in order: binds its image of `targets` (targets.bind(view.screen,
// RenderTargets::imageOf(view.pass))) as the draw framebuffer, runs `pass`, times it
// (wall-clock ms on the calling thread, into the view's cpuMs) and adds the view to the
// returned frame (FrameStats::add; cpuMs and gpuMs of the frame are left to the caller).
// Afterwards the scissor test is off and the colour mask all on. Needs the targets' context
// current; clearing the targets is the caller's (SceneRenderer::beginFrame).
FrameStats forEachView(const std::vector<display::ScreenView>& views, const display::gl::RenderTargets& targets,
                       const ViewPass& pass);

// Per display screen (index = screen, `screenCount` entries): the sum of every field of its
// views' stats in `frame` (whose perView is in the order of `views`). Screens without a view
// stay zero.
std::vector<ViewStats> statsPerScreen(const std::vector<display::ScreenView>& views, const FrameStats& frame,
                                      std::size_t screenCount);

}  // namespace cavewall::render::gl
