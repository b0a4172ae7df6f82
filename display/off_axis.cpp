#include "display/off_axis.h"

#include "display/off_axis_precision.h"

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

namespace {

template <typename T>
struct BasisT {
    glm::vec<3, T> right, up, normal;
    T width, height;
};

template <typename T>
BasisT<T> basisOf(const glm::vec<3, T>& ll, const glm::vec<3, T>& lr, const glm::vec<3, T>& ul) {
    const glm::vec<3, T> rightEdge = lr - ll, upEdge = ul - ll;
    BasisT<T> b;
    b.width = glm::length(rightEdge);
    assert(b.width > T(0) && "screen has a zero-length lower edge");
    b.right = rightEdge / b.width;
    const glm::vec<3, T> upOrtho = upEdge - glm::dot(upEdge, b.right) * b.right;
    b.height = glm::length(upOrtho);
    assert(b.height > T(0) && "screen corners are collinear");
    b.up = upOrtho / b.height;
    b.normal = glm::cross(b.right, b.up);
    return b;
}

template <typename T>
bool isFinite(const glm::vec<3, T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

// Applies the eye guard policy (off_axis.h) to f.eye, setting f.guard and f.eyeDistance.
template <typename T>
void guardEye(const glm::vec<3, T>& ll, const BasisT<T>& b, T minEyeDistance, FrustumT<T>& f) {
    f.guard = EyeGuard::None;
    if (!isFinite(f.eye)) {
        f.guard = EyeGuard::NonFinite;
        const glm::vec<3, T> centre = ll + T(0.5) * b.width * b.right + T(0.5) * b.height * b.up;
        f.eyeDistance = std::max(T(0.5) * std::hypot(b.width, b.height), minEyeDistance);
        f.eye = centre + f.eyeDistance * b.normal;
        return;
    }
    f.eyeDistance = glm::dot(f.eye - ll, b.normal);
    if (f.eyeDistance >= minEyeDistance) return;
    f.guard = f.eyeDistance > T(0) ? EyeGuard::TooClose : EyeGuard::Behind;
    f.eye += (minEyeDistance - f.eyeDistance) * b.normal;
    f.eyeDistance = minEyeDistance;
}

}  // namespace

ScreenBasis screenBasis(const ScreenQuad& screen) {
    const BasisT<double> b = basisOf(screen.lowerLeft, screen.lowerRight, screen.upperLeft);
    return {b.right, b.up, b.normal, b.width, b.height};
}

template <typename T>
FrustumT<T> offAxisFrustumT(const glm::vec<3, T>& ll, const glm::vec<3, T>& lr, const glm::vec<3, T>& ul,
                            const glm::vec<3, T>& eye, T near, T far, T minEyeDistance) {
    assert(minEyeDistance > T(0));
    assert(near > T(0) && near < far);
    const BasisT<T> b = basisOf(ll, lr, ul);
    FrustumT<T> f;
    f.eye = eye;
    guardEye(ll, b, minEyeDistance, f);

    // View: rows are the screen basis, origin at the eye.
    glm::mat<4, 4, T> view(T(1));
    for (int c = 0; c < 3; ++c) {
        view[c][0] = b.right[c];
        view[c][1] = b.up[c];
        view[c][2] = b.normal[c];
    }
    view[3] = glm::vec<4, T>(-glm::dot(b.right, f.eye), -glm::dot(b.up, f.eye), -glm::dot(b.normal, f.eye), T(1));
    f.viewFromFrame = view;

    // Screen extents in view coordinates on the screen plane (z = -d). Working on the plane
    // rather than on the near plane keeps the terms independent of `near`: x_ndc =
    // (2d/W) x/(-z) + (x0 + x1)/W, which is exact at every screen point.
    const glm::vec<3, T> fromEye = ll - f.eye;
    const T x0 = glm::dot(b.right, fromEye), y0 = glm::dot(b.up, fromEye);
    const T d = f.eyeDistance;
    glm::mat<4, 4, T> p(T(0));
    p[0][0] = T(2) * d / b.width;
    p[1][1] = T(2) * d / b.height;
    p[2][0] = (T(2) * x0 + b.width) / b.width;
    p[2][1] = (T(2) * y0 + b.height) / b.height;
    p[2][3] = T(-1);
    // Reversed-Z: z_clip = A z + B with depth(-near) = 1, depth(-far) = 0.
    if (std::isinf(far)) {
        p[2][2] = T(0);
        p[3][2] = near;
    } else {
        p[2][2] = near / (far - near);
        p[3][2] = near * far / (far - near);
    }
    f.clipFromView = p;
    return f;
}

template FrustumT<float> offAxisFrustumT(const glm::vec3&, const glm::vec3&, const glm::vec3&, const glm::vec3&, float,
                                         float, float);
template FrustumT<double> offAxisFrustumT(const glm::dvec3&, const glm::dvec3&, const glm::dvec3&, const glm::dvec3&,
                                          double, double, double);
template FrustumT<long double> offAxisFrustumT(const glm::vec<3, long double>&, const glm::vec<3, long double>&,
                                               const glm::vec<3, long double>&, const glm::vec<3, long double>&,
                                               long double, long double, long double);

OffAxisFrustum offAxisFrustum(const ScreenQuad& screen, glm::dvec3 eye, DepthRange depth, double minEyeDistance) {
    const FrustumT<double> f = offAxisFrustumT(screen.lowerLeft, screen.lowerRight, screen.upperLeft, eye, depth.near,
                                               depth.far, minEyeDistance);
    return {f.viewFromFrame, f.clipFromView, f.eye, f.eyeDistance, f.guard};
}

glm::mat4 eyeRelativeModelView(const OffAxisFrustum& frustum, const glm::dmat4& frameFromModel) {
    return glm::mat4(frustum.viewFromFrame * frameFromModel);
}

}  // namespace cavewall::display
