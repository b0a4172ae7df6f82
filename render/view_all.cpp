#include "render/view_all.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <limits>

namespace cavewall::render {

namespace {

// The four side planes (x = ±w, y = ±w) of a frustum, as unit inward normals through the eye.
std::array<glm::dvec3, 4> sideNormals(const display::OffAxisFrustum& f) {
    const glm::dmat4 m = f.clipFromFrame();
    const glm::dvec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]);
    const glm::dvec4 r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    std::array<glm::dvec3, 4> out;
    const glm::dvec4 planes[4] = {r3 + r0, r3 - r0, r3 + r1, r3 - r1};
    for (int i = 0; i < 4; ++i) out[i] = glm::normalize(glm::dvec3(planes[i]));
    return out;
}

glm::dvec3 screenCentre(const display::ScreenQuad& q) { return 0.5 * (q.lowerRight + q.upperLeft); }

}  // namespace

ViewAll viewAll(const display::Display& display, const display::HeadPose& head, const scenes::Bounds& bounds) {
    ViewAll out;
    if (bounds.empty() || display.screens().empty()) return out;
    const glm::dvec3 forward = head.orientation * glm::dvec3(0, 0, -1);
    double best = -std::numeric_limits<double>::infinity();
    for (int s = 0; s < static_cast<int>(display.screens().size()); ++s) {
        const double facing = glm::dot(forward, glm::normalize(screenCentre(display.quad(s)) - head.position));
        if (facing > best) {
            best = facing;
            out.screen = s;
        }
    }
    const display::OffAxisFrustum f = display::offAxisFrustum(display.quad(out.screen), head.position,
                                                              display.depthRange(), display.config().minEyeDistance);
    const glm::dvec3 ray = glm::normalize(screenCentre(display.quad(out.screen)) - f.eye);
    const double radius = std::max(0.5 * glm::length(bounds.size()), 1e-6);
    // Distance of e + d * ray from a side plane through the eye is d * (n . ray): at least r.
    double distance = radius + 1.01 * display.depthRange().near;
    for (const glm::dvec3& n : sideNormals(f)) distance = std::max(distance, radius / std::max(glm::dot(n, ray), 1e-9));
    out.distance = distance;
    // worldFromCave maps the cave point e + d * ray onto the sphere's centre.
    out.worldFromCave = glm::translate(glm::dmat4(1.0), bounds.centre() - (f.eye + distance * ray));
    return out;
}

}  // namespace cavewall::render
