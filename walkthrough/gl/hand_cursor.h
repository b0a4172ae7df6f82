#pragma once
// The hand cursor: the tracked hand (or the desktop fallback's hand at the view centre) drawn as
// a small flat hand icon with a pointing ray, so the user sees where navigation and picking aim.
//
// Plain data in (walkthrough::HandCursorPose), no dependency on the input library: the caller converts
// input::HandCursor.
// The icon is a palm (6 cm x 8 cm) with a pointing finger along the ray, facing up in the
// hand's frame (the hand points along its -Z, +Y up); the ray is a line of `rayLength` metres.
// Both are unlit flat colours, depth-tested so the scene can hide them.

#include "display/gl/gl_object.h"
#include "render/gl/scene_renderer.h"
#include "display/off_axis.h"
#include "walkthrough/frame_types.h"

#include <glm/gtc/quaternion.hpp>

namespace cavewall::walkthrough::gl {

using walkthrough::HandCursorPose;  // walkthrough/frame_types.h

class HandCursorPass {
public:
    // Builds the program; throws Error when the shaders do not build.
    HandCursorPass();
    // Draws the cursor for one view (cave frame frustum) into the bound framebuffer.
    void draw(const HandCursorPose& hand, const display::OffAxisFrustum& frustum, display::FrameStats& stats);

private:
    display::gl::GlObject _program, _vertexArray, _buffer;
    GLint _projection = -1, _color = -1;
};

}  // namespace cavewall::walkthrough::gl
