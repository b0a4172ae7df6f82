#pragma once
// What the depth wall tests share (depth_wall_pass_test.cpp, wall_depth_test.cpp): a 4 m x 3 m
// wall with a card behind it, the full geometry seen through the wall, and a wall pass drawn on
// a cleared target. Needs a current context.

#include "display/off_axis.h"
#include "render/gl/scene_renderer.h"
#include "scenes/primitives.h"
#include "walls/gl/offscreen_target.h"

#include <glm/gtc/matrix_transform.hpp>

#include <string>
#include <vector>

namespace cavewall::testing {

inline const display::ScreenQuad kCardWall{{-2, 0, 0}, {2, 0, 0}, {-2, 3, 0}};  // 4 m x 3 m at z = 0, facing +z
inline const glm::dvec3 kCardWallSample(0.0, 1.5, 3.0);                         // 3 m in front of its middle

// A checkerboard back plane 4 m behind the wall (2 m tiles, two greys) and a red card (a 1 m x
// 1 m x 0.2 m box) centred at (cardX, 1.9, -1.1), so that its front face is 1 m behind the
// wall: objects 0 ("back") and 1 ("card"), both content, lit by ambient light alone (so colour
// does not depend on the eye).
inline scenes::Scene cardScene(const std::string& name, double cardX) {
    scenes::Scene s;
    s.name = name;
    s.meshes.push_back(scenes::makeTiledQuad({-5, -1.5, -4}, {10, 0, 0}, {0, 6, 0}, 5, 3, {0.55f, 0.55f, 0.55f, 1},
                                             {0.2f, 0.2f, 0.25f, 1}));
    scenes::addObject(s, 0, glm::dmat4(1.0), "back");
    s.meshes.push_back(scenes::makeBox({1.0f, 1.0f, 0.2f}, {0.9f, 0.1f, 0.1f, 1}));
    scenes::addObject(s, 1, glm::translate(glm::dmat4(1.0), glm::dvec3(cardX, 1.9, -1.1)), "card");
    return s;
}

// `objects` of `scene` through `frustum` into the whole of `target`, cleared to transparent
// black first.
inline void renderGeometry(const scenes::Scene& scene, const std::vector<int>& objects,
                           const display::OffAxisFrustum& frustum, const walls::gl::OffscreenTarget& target) {
    render::gl::SceneRenderer renderer(scene, render::gl::RenderSettings{glm::vec4(0.0f), 1.0f});
    render::gl::ViewTarget view;
    view.framebuffer = target.framebuffer();
    view.viewport = {0, 0, target.size().x, target.size().y};
    view.clearColor = glm::vec4(0.0f);
    render::DrawFilter filter;
    filter.objects = &objects;
    renderer.renderFrustum(frustum, glm::dmat4(1.0), view, filter);
}

// Clears `target` to transparent black, sets the clip control the passes draw with and runs
// `draw(stats)`; returns the stats.
template <typename Draw>
display::FrameStats drawOnCleared(const walls::gl::OffscreenTarget& target, const Draw& draw) {
    target.bindAndClear(glm::vec4(0.0f));
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    display::FrameStats stats;
    draw(stats);
    return stats;
}

}  // namespace cavewall::testing
