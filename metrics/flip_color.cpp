#include "metrics/flip_color.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace cavewall::metrics {

namespace {

// Linear sRGB (D65) to CIE XYZ and back; glm matrices are column-major, so these are written
// transposed: each line is one column.
const glm::dmat3 kXyzFromRgb{0.4124564, 0.2126729, 0.0193339,  //
                             0.3575761, 0.7151522, 0.1191920,  //
                             0.1804375, 0.0721750, 0.9503041};
const glm::dmat3 kRgbFromXyz = glm::inverse(kXyzFromRgb);
const glm::dvec3 kWhite = kXyzFromRgb * glm::dvec3(1.0);  // (Xn, Yn, Zn)

constexpr double kQc = 0.7, kPc = 0.4, kPt = 0.95;  // colour error exponent and remapping

// The cube root of t in (0.008, 1.1]: an exponent-thirding guess, then two Halley steps (each
// cubes the relative error: 3 % -> 1e-5 -> 1e-15). std::cbrt dominated FLIP's run time.
double cubeRoot(double t) {
    std::uint64_t bits = std::bit_cast<std::uint64_t>(t);
    bits = bits / 3 + (std::uint64_t{0x3FF} << 52) / 3 * 2;  // exponent e -> about e / 3
    double y = std::bit_cast<double>(bits);
    for (int i = 0; i < 2; ++i) {
        const double y3 = y * y * y;
        y *= (y3 + 2.0 * t) / (2.0 * y3 + t);
    }
    return y;
}

double labF(double t) {
    constexpr double kDelta = 6.0 / 29.0;
    return t > kDelta * kDelta * kDelta ? cubeRoot(t) : t / (3.0 * kDelta * kDelta) + 4.0 / 29.0;
}

// Linear RGB (clamped to [0, 1]) to Hunt-adjusted CIELAB.
glm::dvec3 huntLab(glm::dvec3 rgb) {
    const glm::dvec3 xyz = kXyzFromRgb * glm::clamp(rgb, 0.0, 1.0) / kWhite;
    const double fx = labF(xyz.x), fy = labF(xyz.y), fz = labF(xyz.z);
    const double l = 116.0 * fy - 16.0;
    return {l, 0.01 * l * 500.0 * (fx - fy), 0.01 * l * 200.0 * (fy - fz)};
}

}  // namespace

std::array<float, 256> decodeTable(ColorEncoding encoding) {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
        const double v = i / 255.0;
        const double srgb = v <= 0.04045 ? v / 12.92 : std::pow((v + 0.055) / 1.055, 2.4);
        t[i] = static_cast<float>(encoding == ColorEncoding::Srgb ? srgb : v);
    }
    return t;
}

glm::dvec3 opponentFromLinear(glm::dvec3 rgb) {
    const glm::dvec3 xyz = kXyzFromRgb * rgb / kWhite;
    return {116.0 * xyz.y - 16.0, 500.0 * (xyz.x - xyz.y), 200.0 * (xyz.y - xyz.z)};
}

glm::dvec3 huntLabFromOpponent(glm::dvec3 o) {
    const double y = (o.x + 16.0) / 116.0;
    const glm::dvec3 xyz = glm::dvec3(o.y / 500.0 + y, y, y - o.z / 200.0) * kWhite;
    return huntLab(kRgbFromXyz * xyz);
}

double hyab(glm::dvec3 a, glm::dvec3 b) {
    const double da = a.y - b.y, db = a.z - b.z;
    return std::abs(a.x - b.x) + std::sqrt(da * da + db * db);
}

double flipColorError(double difference) {
    // The largest colour difference within the gamut, raised to qc.
    static const double kCmax = std::pow(hyab(huntLab({0, 1, 0}), huntLab({0, 0, 1})), kQc);
    // Single precision is ample here, and powf is several times faster than pow.
    const double e = std::pow(static_cast<float>(difference), static_cast<float>(kQc));
    if (e < kPc * kCmax) return kPt / (kPc * kCmax) * e;
    return std::min(1.0, kPt + (e - kPc * kCmax) / (kCmax - kPc * kCmax) * (1.0 - kPt));
}

}  // namespace cavewall::metrics
