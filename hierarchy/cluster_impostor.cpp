#include "hierarchy/cluster_impostor.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace cavewall::hierarchy {

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The outward normal, up and right of a face (right x up = normal).
struct FaceFrame {
    glm::dvec3 normal, up, right;
};

FaceFrame faceFrame(int face) {
    assert(face >= 0 && face < kBoxFaces);
    const glm::dvec3 n = faceNormal(face);
    glm::dvec3 up(0.0, 1.0, 0.0);
    if (face / 2 == 1) up = face == 2 ? glm::dvec3(0.0, 0.0, -1.0) : glm::dvec3(0.0, 0.0, 1.0);
    return {n, up, glm::cross(up, n)};
}

glm::dvec3 faceCentre(const scenes::Bounds& box, int face) {
    return box.centre() + 0.5 * glm::abs(glm::dot(box.size(), faceNormal(face))) * faceNormal(face);
}

float srgbDecode(float e) { return e <= 0.04045f ? e / 12.92f : std::pow((e + 0.055f) / 1.055f, 2.4f); }

}  // namespace

scenes::Bounds impostorBox(const scenes::Bounds& bounds) {
    assert(!bounds.empty());
    const glm::dvec3 size = bounds.size();
    const double least = std::max(0.01 * std::max({size.x, size.y, size.z}), 1e-3);
    scenes::Bounds box = bounds;
    for (int a = 0; a < 3; ++a)
        if (size[a] < least) {
            const double c = bounds.centre()[a];
            box.min[a] = c - 0.5 * least;
            box.max[a] = c + 0.5 * least;
        }
    return box;
}

glm::dvec3 faceNormal(int face) {
    glm::dvec3 n(0.0);
    n[face / 2] = face % 2 == 0 ? 1.0 : -1.0;
    return n;
}

display::ScreenQuad boxFace(const scenes::Bounds& box, int face) {
    const FaceFrame f = faceFrame(face);
    const glm::dvec3 c = faceCentre(box, face);
    const glm::dvec3 size = box.size();
    const glm::dvec3 r = 0.5 * std::abs(glm::dot(size, f.right)) * f.right;
    const glm::dvec3 u = 0.5 * std::abs(glm::dot(size, f.up)) * f.up;
    return {c - r - u, c + r - u, c - r + u};
}

bool faceTowards(const scenes::Bounds& box, int face, glm::dvec3 eye) {
    return glm::dot(eye - faceCentre(box, face), faceNormal(face)) > 0.0;
}

int viewRegion(const scenes::Bounds& box, int face, glm::dvec3 eye) {
    const FaceFrame f = faceFrame(face);
    const glm::dvec3 d = eye - faceCentre(box, face);
    const double x = glm::dot(d, f.right), y = glm::dot(d, f.up), z = glm::dot(d, f.normal);
    if (std::atan2(std::hypot(x, y), z) < kCentreRegionDeg * kDegree) return 0;
    if (std::abs(x) >= std::abs(y)) return x > 0.0 ? 1 : 2;
    return y > 0.0 ? 3 : 4;
}

glm::dvec3 samplingEye(const scenes::Bounds& box, int face, int region) {
    assert(region >= 0 && region < kFaceRegions);
    const FaceFrame f = faceFrame(face);
    const glm::dvec3 sides[kFaceRegions] = {glm::dvec3(0.0), f.right, -f.right, f.up, -f.up};
    const double tilt = region == 0 ? 0.0 : kRegionTiltDeg * kDegree;
    const glm::dvec3 direction = std::cos(tilt) * f.normal + std::sin(tilt) * sides[region];
    return faceCentre(box, face) + kSamplingDistance * glm::length(box.size()) * direction;
}

glm::ivec2 faceResolution(const scenes::Bounds& box, int face, int maxResolution) {
    const FaceFrame f = faceFrame(face);
    const double w = std::abs(glm::dot(box.size(), f.right)), h = std::abs(glm::dot(box.size(), f.up));
    const double longer = std::max({w, h, 1e-12});
    return {std::max(4, static_cast<int>(std::lround(maxResolution * w / longer))),
            std::max(4, static_cast<int>(std::lround(maxResolution * h / longer)))};
}

FaceAverage faceAverage(const scenes::Image& premultiplied) {
    const std::size_t texels = static_cast<std::size_t>(premultiplied.width) * premultiplied.height;
    glm::dvec3 sum(0.0);
    double alpha = 0.0;
    for (std::size_t i = 0; i < texels; ++i) {
        const std::uint8_t* p = &premultiplied.rgba[4 * i];
        const double a = p[3] / 255.0;
        if (a <= 0.0) continue;
        for (int c = 0; c < 3; ++c) sum[c] += srgbDecode(p[c] / 255.0f);
        alpha += a;
    }
    FaceAverage average;
    if (alpha > 0.0) average.linearColour = glm::vec3(sum / alpha);
    average.coverage = texels > 0 ? static_cast<float>(alpha / static_cast<double>(texels)) : 0.0f;
    return average;
}

display::ScreenQuad averageFaceQuad(const display::ScreenQuad& face, float coverage) {
    const double s = std::sqrt(std::clamp(static_cast<double>(coverage), 0.0, 1.0));
    const glm::dvec3 centre = 0.5 * (face.lowerRight + face.upperLeft);
    auto scaled = [&](glm::dvec3 p) { return centre + s * (p - centre); };
    return {scaled(face.lowerLeft), scaled(face.lowerRight), scaled(face.upperLeft)};
}

std::array<glm::dvec3, kAccuracyDirections> accuracyDirections() {
    const double e = 25.0 * kDegree, high = 60.0 * kDegree;
    const double c = std::cos(e), s = std::sin(e);
    return {
        glm::dvec3(c, s, 0.0),
        glm::dvec3(-c, s, 0.0),
        glm::dvec3(0.0, s, c),
        glm::dvec3(0.0, s, -c),
        glm::dvec3(0.0, 1.0, 0.0),
        glm::normalize(glm::dvec3(std::cos(high) / std::sqrt(2.0), std::sin(high), std::cos(high) / std::sqrt(2.0)))};
}

int nearestAccuracyDirection(const scenes::Bounds& box, glm::dvec3 eye) {
    const glm::dvec3 d = eye - box.centre();
    const auto directions = accuracyDirections();
    int best = 0;
    for (int i = 1; i < kAccuracyDirections; ++i)
        if (glm::dot(directions[i], d) > glm::dot(directions[best], d)) best = i;
    return best;
}

BoxView viewOfBox(const scenes::Bounds& box, glm::dvec3 direction) {
    const double d = glm::length(box.size());
    const glm::dvec3 helper = std::abs(direction.y) > 0.9 ? glm::dvec3(0, 0, -1) : glm::dvec3(0, 1, 0);
    const glm::dvec3 right = glm::normalize(glm::cross(helper, direction));
    const glm::dvec3 up = glm::cross(direction, right);
    const double half = 0.75 * d;
    const glm::dvec3 c = box.centre();
    return {{c - half * right - half * up, c + half * right - half * up, c - half * right + half * up},
            c + 2.5 * d * direction};
}

double accuracyFromFlip(double flipMean) { return std::clamp(1.0 - flipMean, 0.0, 1.0); }

}  // namespace cavewall::hierarchy
