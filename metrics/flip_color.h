#pragma once
// The colour science under FLIP (metrics/flip.h): byte decoding, linear sRGB to the opponent
// space YyCxCz, back to CIELAB with the Hunt adjustment, the HyAB difference and FLIP's
// remapping of it onto [0, 1]. Reference white: XYZ of linear RGB (1, 1, 1) (D65, Y = 1).

#include "metrics/flip.h"

#include <glm/glm.hpp>

#include <array>

namespace cavewall::metrics {

// Linear light in [0, 1] of each byte value: the IEC 61966-2-1 sRGB curve, or value / 255.
std::array<float, 256> decodeTable(ColorEncoding encoding);

// (Yy, Cx, Cz) of linear sRGB: Yy = 116 Y/Yn - 16, Cx = 500 (X/Xn - Y/Yn), Cz = 200 (Y/Yn - Z/Zn).
// Linear in the input, so filters commute with it.
glm::dvec3 opponentFromLinear(glm::dvec3 rgb);

// (L*, a*, b*) with a* and b* scaled by 0.01 L* (the Hunt adjustment) of an opponent colour,
// after clamping its linear RGB to [0, 1].
glm::dvec3 huntLabFromOpponent(glm::dvec3 yyCxCz);

// HyAB: |dL*| + sqrt(da*² + db*²).
double hyab(glm::dvec3 a, glm::dvec3 b);

// FLIP's colour error of a HyAB difference, in [0, 1]: difference^0.7 mapped against cmax, the
// HyAB of Hunt-adjusted green and blue raised to 0.7, linearly onto [0, 0.95) below 0.4 cmax
// and onto [0.95, 1] above (clamped to 1).
double flipColorError(double difference);

}  // namespace cavewall::metrics
