#include "render/portal_cull.h"

#include <cmath>

namespace cavewall::render {

namespace {

// The largest value of the affine function `plane` (n, d: n . x + d) over `box`.
double maxOver(const glm::dvec4& plane, const scenes::Bounds& box) {
    const glm::dvec3 n(plane);
    const glm::dvec3 far(n.x >= 0.0 ? box.max.x : box.min.x, n.y >= 0.0 ? box.max.y : box.min.y,
                         n.z >= 0.0 ? box.max.z : box.min.z);
    return glm::dot(n, far) + plane.w;
}

// The plane through `a` with normal `n`, as (n, -n . a).
glm::dvec4 planeThrough(glm::dvec3 n, glm::dvec3 a) { return {n, -glm::dot(n, a)}; }

// `q` with slack `s` seen from `eye` (portal_cull.h): grown by s past its edges, moved s towards
// its front, and grown there to hold the grown quad moved s back as the eye sees it. A point
// (which the view leaves open) when the eye is not clear in front of the moved plane.
display::ScreenQuad withSlack(const display::ScreenQuad& q, double s, glm::dvec3 eye) {
    glm::dvec3 u = q.lowerRight - q.lowerLeft, v = q.upperLeft - q.lowerLeft;
    const glm::dvec3 n = glm::normalize(glm::cross(u, v));
    const double lu = glm::length(u), lv = glm::length(v);
    const glm::dvec3 origin = q.lowerLeft - s * (u / lu + v / lv) + s * n;
    u *= (lu + 2.0 * s) / lu;
    v *= (lv + 2.0 * s) / lv;
    const double near = glm::dot(n, eye - origin);  // the eye's height over the moved plane
    if (!(near >= kPortalEyeClearance)) return {origin, origin, origin};
    // Coordinates in the moved plane along u and v (a parallelogram: the dual basis).
    const glm::dmat2 g(glm::dot(u, u), glm::dot(u, v), glm::dot(u, v), glm::dot(v, v));
    const glm::dmat2 inv = glm::inverse(g);
    glm::dvec2 lo(0.0), hi(1.0);
    for (int k = 0; k < 4; ++k) {
        const glm::dvec3 back = origin + double(k & 1) * u + double(k >> 1) * v - 2.0 * s * n;
        const glm::dvec3 seen = eye + (back - eye) * (near / (near + 2.0 * s));  // onto the moved plane
        const glm::dvec2 st = inv * glm::dvec2(glm::dot(seen - origin, u), glm::dot(seen - origin, v));
        lo = glm::min(lo, st);
        hi = glm::max(hi, st);
    }
    const glm::dvec3 ll = origin + lo.x * u + lo.y * v;
    return {ll, ll + (hi.x - lo.x) * u, ll + (hi.y - lo.y) * v};
}

}  // namespace

PortalView::PortalView(const PortalSets& sets, glm::dvec3 eye) : _sets(sets) {
    _pyramids.resize(sets.portals.size());
    for (std::size_t i = 0; i < sets.portals.size(); ++i) {
        const display::ScreenQuad& q =
            sets.slack > 0.0 ? withSlack(sets.portals[i], sets.slack, eye) : sets.portals[i];
        const glm::dvec3 u = q.lowerRight - q.lowerLeft, v = q.upperLeft - q.lowerLeft;
        const glm::dvec3 n = glm::cross(u, v);
        const double length = glm::length(n);
        Pyramid& p = _pyramids[i];
        if (!(length > 0.0) || !std::isfinite(length)) continue;  // degenerate: open
        const glm::dvec4 plane = planeThrough(n / length, q.lowerLeft);
        if (!(glm::dot(glm::dvec3(plane), eye) + plane.w >= kPortalEyeClearance)) continue;
        const glm::dvec3 centre = q.lowerLeft + 0.5 * (u + v);
        const std::array<glm::dvec3, 4> corners = {q.lowerLeft, q.lowerRight, q.lowerRight + v, q.upperLeft};
        for (int k = 0; k < 4; ++k) {
            const glm::dvec3 a = corners[k], b = corners[(k + 1) % 4];
            glm::dvec4 side = planeThrough(glm::cross(a - eye, b - eye), eye);
            if (glm::dot(glm::dvec3(side), centre) + side.w < 0.0) side = -side;
            p.sides[k] = side;
        }
        p.plane = plane;
        p.open = false;
    }
}

bool PortalView::seen(const Pyramid& p, const scenes::Bounds& box) const {
    if (p.open || box.empty()) return true;
    if (-maxOver(-p.plane, box) > 0.0) return false;  // wholly in front of the portal
    for (const glm::dvec4& side : p.sides)
        if (maxOver(side, box) < 0.0) return false;
    return true;
}

bool PortalView::visible(int object, const scenes::Bounds& box) const {
    if (object < 0 || object >= static_cast<int>(_sets.objectSet.size())) return true;
    const int set = _sets.objectSet[object];
    if (set < 0 || set >= static_cast<int>(_sets.sets.size())) return true;
    for (int chain : _sets.sets[set]) {
        bool through = true;
        for (int portal : _sets.chains[chain])
            if (!seen(_pyramids[portal], box)) {
                through = false;
                break;
            }
        if (through) return true;
    }
    return false;
}

bool seenThrough(const scenes::Bounds& box, glm::dvec3 eye, const display::ScreenQuad& portal) {
    const PortalSets sets{{portal}, 0.0, {{0}}, {{0}}, {0}};
    return PortalView(sets, eye).visible(0, box);
}

}  // namespace cavewall::render
