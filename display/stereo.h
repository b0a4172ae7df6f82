#pragma once
// Stereo: where each eye is, and how each eye's image is laid out in a screen's output.
//
// Eyes sit at the head position ± half the eye separation along the head's x axis (the head
// frame looks down -Z, +X to the right). Every mode renders the same per-eye off-axis frusta;
// the modes differ only in where the pixels go:
//   mono          one image, the centre (cyclopean) eye
//   separate      two images per screen, "<screen>-left" and "<screen>-right"
//   side-by-side  one image, left eye in the left half, right eye in the right half
//   top-bottom    one image, left eye in the top half, right eye in the bottom half
//   anaglyph      one image, left eye written to red only, right eye to green and blue
//   quad-buffer   GL_BACK_LEFT / GL_BACK_RIGHT of a stereo window (needs a context that offers it)

#include "config/display_config.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <vector>

namespace cavewall::display {

enum class Eye { Center, Left, Right };
const char* toString(Eye eye);

// The eye position in the head's frame of reference: head + orientation * (±separation/2, 0, 0).
glm::dvec3 eyePosition(glm::dvec3 head, const glm::dquat& orientation, double separation, Eye eye);

struct Viewport {
    int x = 0, y = 0, width = 0, height = 0;  // pixels, origin lower-left (OpenGL)
    bool operator==(const Viewport&) const = default;
};

// One eye's pass into a screen's output.
struct EyePass {
    Eye eye = Eye::Center;
    int image = 0;  // output image index (separate: 0 = left, 1 = right)
    Viewport viewport;
    glm::bvec4 colorMask{true};  // anaglyph masks
    bool backRight = false;      // quad-buffer: draw into GL_BACK_RIGHT
};

// The passes for a stereo mode on a screen of `resolution` pixels, in drawing order.
std::vector<EyePass> eyePasses(config::StereoMode mode, glm::ivec2 resolution);

// Number of output images per screen (2 for separate, else 1).
int imagesPerScreen(config::StereoMode mode);

}  // namespace cavewall::display
