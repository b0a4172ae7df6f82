#include "display/off_axis.h"

#include <cassert>
#include <cmath>

namespace cavewall::display {

const char* toString(EyeGuard guard) {
    switch (guard) {
    case EyeGuard::None: return "none";
    case EyeGuard::TooClose: return "too-close";
    case EyeGuard::Behind: return "behind";
    case EyeGuard::NonFinite: return "non-finite";
    }
    return "?";
}

ScreenBasis screenBasis(const ScreenQuad& screen) {
    const glm::dvec3 rightEdge = screen.lowerRight - screen.lowerLeft;
    const glm::dvec3 upEdge = screen.upperLeft - screen.lowerLeft;
    ScreenBasis b;
    b.width = glm::length(rightEdge);
    assert(b.width > 0.0 && "screen has a zero-length lower edge");
    b.right = rightEdge / b.width;
    const glm::dvec3 upOrtho = upEdge - glm::dot(upEdge, b.right) * b.right;
    b.height = glm::length(upOrtho);
    assert(b.height > 0.0 && "screen corners are collinear");
    b.up = upOrtho / b.height;
    b.normal = glm::cross(b.right, b.up);
    return b;
}

namespace {

bool isFinite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Applies the eye guard policy; returns the eye to use and its distance from the plane.
glm::dvec3 guardEye(const ScreenQuad& screen, const ScreenBasis& b, glm::dvec3 eye,
                    double minEyeDistance, EyeGuard& guard, double& distance) {
    guard = EyeGuard::None;
    if (!isFinite(eye)) {
        guard = EyeGuard::NonFinite;
        const glm::dvec3 centre = screen.lowerLeft + 0.5 * b.width * b.right + 0.5 * b.height * b.up;
        distance = std::max(0.5 * std::hypot(b.width, b.height), minEyeDistance);
        return centre + distance * b.normal;
    }
    distance = glm::dot(eye - screen.lowerLeft, b.normal);
    if (distance >= minEyeDistance) return eye;
    guard = distance > 0.0 ? EyeGuard::TooClose : EyeGuard::Behind;
    const glm::dvec3 moved = eye + (minEyeDistance - distance) * b.normal;
    distance = minEyeDistance;
    return moved;
}

}  // namespace

OffAxisFrustum offAxisFrustum(const ScreenQuad& screen, glm::dvec3 eye, DepthRange depth,
                              double minEyeDistance) {
    assert(minEyeDistance > 0.0);
    assert(depth.near > 0.0 && depth.near < depth.far);
    const ScreenBasis b = screenBasis(screen);
    OffAxisFrustum f;
    f.eye = guardEye(screen, b, eye, minEyeDistance, f.guard, f.eyeDistance);

    // View: rows are the screen basis, origin at the eye.
    glm::dmat4 view(1.0);
    for (int c = 0; c < 3; ++c) {
        view[c][0] = b.right[c];
        view[c][1] = b.up[c];
        view[c][2] = b.normal[c];
    }
    const glm::dvec3 t = -glm::dvec3(glm::dot(b.right, f.eye), glm::dot(b.up, f.eye), glm::dot(b.normal, f.eye));
    view[3] = glm::dvec4(t, 1.0);
    f.viewFromFrame = view;

    // Screen extents in view coordinates on the screen plane (z = -d). Working on the plane
    // rather than on the near plane keeps the terms independent of `near`: x_ndc =
    // (2d/W) x/(-z) + (x0 + x1)/W, which is exact at every screen point.
    const glm::dvec3 fromEye = screen.lowerLeft - f.eye;
    const double x0 = glm::dot(b.right, fromEye), x1 = x0 + b.width;
    const double y0 = glm::dot(b.up, fromEye), y1 = y0 + b.height;
    const double d = f.eyeDistance;

    glm::dmat4 p(0.0);
    p[0][0] = 2.0 * d / b.width;
    p[1][1] = 2.0 * d / b.height;
    p[2][0] = (x0 + x1) / b.width;
    p[2][1] = (y0 + y1) / b.height;
    p[2][3] = -1.0;
    // Reversed-Z: z_clip = A z + B with depth(-near) = 1, depth(-far) = 0.
    if (std::isinf(depth.far)) {
        p[2][2] = 0.0;
        p[3][2] = depth.near;
    } else {
        p[2][2] = depth.near / (depth.far - depth.near);
        p[3][2] = depth.near * depth.far / (depth.far - depth.near);
    }
    f.clipFromView = p;
    return f;
}

glm::mat4 eyeRelativeModelView(const OffAxisFrustum& frustum, const glm::dmat4& frameFromModel) {
    return glm::mat4(frustum.viewFromFrame * frameFromModel);
}

}  // namespace cavewall::display
