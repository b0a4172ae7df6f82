#pragma once
// From a view's depth buffer to the distance from its eye to what each pixel shows: the
// input of the stereo error (metrics/stereo_error.h).
//
// Depth is the reversed-Z window depth of display/off_axis.h (near plane 1, far plane 0, for
// glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE)). A pixel's centre and depth are taken back
// through the inverse of the view's clipFromView into the view frame, whose origin is the eye;
// the distance is that point's length in metres. Depth 0 (the cleared buffer: nothing drawn, or
// the far plane) gives +infinity; a depth that is NaN or outside [0, 1] gives NaN (invalid).

#include "display/off_axis.h"

#include <glm/glm.hpp>

#include <vector>

namespace cavewall::display {

// Distances (metres) for a viewport of `size` pixels of `frustum`'s view; `depth` has
// size.x * size.y values, rows top to bottom (as images are stored), and so does the result.
// `depth` of the wrong length is a programmer error (assert).
std::vector<float> eyeDistances(const OffAxisFrustum& frustum, glm::ivec2 size, const std::vector<float>& depth);

}  // namespace cavewall::display
