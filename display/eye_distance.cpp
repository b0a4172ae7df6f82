#include "display/eye_distance.h"

#include <cassert>
#include <cmath>
#include <limits>

namespace cavewall::display {

std::vector<float> eyeDistances(const OffAxisFrustum& frustum, glm::ivec2 size, const std::vector<float>& depth) {
    assert(size.x > 0 && size.y > 0 && depth.size() == static_cast<std::size_t>(size.x) * size.y);
    const glm::dmat4 viewFromClip = glm::inverse(frustum.clipFromView);
    std::vector<float> out(depth.size());
    for (int row = 0; row < size.y; ++row)
        for (int x = 0; x < size.x; ++x) {
            const std::size_t i = static_cast<std::size_t>(row) * size.x + x;
            const double d = depth[i];
            if (!(d >= 0.0 && d <= 1.0)) {
                out[i] = std::numeric_limits<float>::quiet_NaN();
                continue;
            }
            if (d == 0.0) {
                out[i] = std::numeric_limits<float>::infinity();
                continue;
            }
            // Row 0 is the top: normalised device y runs up from the bottom row.
            const glm::dvec2 ndc((x + 0.5) / size.x * 2.0 - 1.0, 1.0 - (row + 0.5) / size.y * 2.0);
            const glm::dvec4 view = viewFromClip * glm::dvec4(ndc, d, 1.0);
            out[i] = static_cast<float>(glm::length(glm::dvec3(view) / view.w));
        }
    return out;
}

}  // namespace cavewall::display
