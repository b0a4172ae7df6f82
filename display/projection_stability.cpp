#include "display/projection_stability.h"

#include "config/json_reader.h"
#include "display/off_axis_precision.h"
#include "display/warp.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace cavewall::display {

namespace {

using ldvec3 = glm::vec<3, long double>;
constexpr double kPixels = 1024.0;
constexpr long double kInf = std::numeric_limits<long double>::infinity();

struct Setup {
    glm::dvec3 lowerLeft, lowerRight, upperLeft, eye;
    double minEyeDistance;
};

// Probe points: a 5x5 grid on the screen, and the same directions at twice the distance.
std::vector<glm::dvec3> probes(const Setup& s) {
    std::vector<glm::dvec3> out;
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            const glm::dvec3 p =
                s.lowerLeft + 0.25 * i * (s.lowerRight - s.lowerLeft) + 0.25 * j * (s.upperLeft - s.lowerLeft);
            out.push_back(p);
            out.push_back(s.eye + 2.0 * (p - s.eye));
        }
    return out;
}

template <typename T>
glm::vec<2, T> ndcOf(const FrustumT<T>& f, const glm::vec<3, T>& p) {
    const glm::vec<4, T> c = f.clipFromView * f.viewFromFrame * glm::vec<4, T>(p, T(1));
    return {c.x / c.w, c.y / c.w};
}

// cavewall's CPU path: the view translation is cancelled against a model placed at the eye
// before anything is rounded, and points are taken relative to the eye (model-local).
glm::dvec2 eyeRelativeNdc(const FrustumT<double>& f, glm::dvec3 p) {
    const glm::dmat4 viewFromEye = f.viewFromFrame * glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0),
                                                                glm::dvec4(0, 0, 1, 0), glm::dvec4(f.eye, 1));
    const glm::dvec4 c = f.clipFromView * viewFromEye * glm::dvec4(p - f.eye, 1.0);
    return {c.x / c.w, c.y / c.w};
}

template <typename T>
FrustumT<T> frustumIn(const Setup& s) {
    using V = glm::vec<3, T>;
    return offAxisFrustumT<T>(V(s.lowerLeft), V(s.lowerRight), V(s.upperLeft), V(s.eye), T(1e-3), T(kInf),
                              T(s.minEyeDistance));
}

// Worst pixel error against the long-double reference over the probes: the naive float path
// (T = float, world-space maths) or cavewall's double path (T = double, eye-relative).
template <typename T>
double worstPixelError(const Setup& s) {
    const FrustumT<T> f = frustumIn<T>(s);
    const FrustumT<long double> ref = frustumIn<long double>(s);
    double worst = 0.0;
    for (const glm::dvec3& p : probes(s)) {
        glm::dvec2 n;
        if constexpr (std::is_same_v<T, double>)
            n = eyeRelativeNdc(f, p);
        else
            n = glm::dvec2(ndcOf(f, glm::vec<3, T>(p)));
        const glm::vec<2, long double> r = ndcOf(ref, ldvec3(p));
        const double e = static_cast<double>(std::max(std::abs(n.x - r.x), std::abs(n.y - r.y)));
        worst = std::max(worst, std::isfinite(e) ? e * kPixels / 2 : std::numeric_limits<double>::infinity());
    }
    return worst;
}

Setup frontWall(double distance, glm::dvec3 offset = glm::dvec3(0.0)) {
    // cave4's front wall with an off-centre eye: 0.7 m right of the left edge, 0.9 m up.
    return {glm::dvec3(-1.5, 0, -1.5) + offset, glm::dvec3(1.5, 0, -1.5) + offset, glm::dvec3(-1.5, 3, -1.5) + offset,
            glm::dvec3(-0.8, 0.9, -1.5 + distance) + offset, 1e-12};
}

// cavewall's GPU path: double frustum, float eye-relative model-view of eye-local points.
double eyeRelativePixelError(const Setup& s) {
    const FrustumT<double> f = frustumIn<double>(s);
    const FrustumT<long double> ref = frustumIn<long double>(s);
    const glm::dmat4 frameFromModel =
        glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(s.eye, 1));
    const glm::mat4 clip(f.clipFromView);
    const glm::mat4 modelView(f.viewFromFrame * frameFromModel);
    double worst = 0.0;
    for (const glm::dvec3& p : probes(s)) {
        const glm::vec4 c = clip * modelView * glm::vec4(glm::vec3(p - s.eye), 1.0f);
        const glm::vec<2, long double> r = ndcOf(ref, ldvec3(p));
        const double e =
            std::max(std::abs(c.x / c.w - static_cast<double>(r.x)), std::abs(c.y / c.w - static_cast<double>(r.y)));
        worst = std::max(worst, e * kPixels / 2);
    }
    return worst;
}

// Depth-order inversions among distances 0.1 % apart from near to min(far, 1e6 * near).
template <typename DepthFn>
double inversions(double near, double far, DepthFn depth) {
    int count = 0;
    float previous = std::numeric_limits<float>::quiet_NaN();
    for (double z = near; z <= std::min(far, 1e9 * near); z *= 1.001) {
        const float d = depth(z);
        if (!(std::isnan(previous) || d != previous)) ++count;  // equal depths lose the order
        previous = d;
    }
    return count;
}

std::string sci(double v) { return config::formatNumber(v); }

}  // namespace

std::vector<StabilityRow> eyeDistanceCases() {
    std::vector<StabilityRow> rows;
    for (double d = 1e-9; d <= 1.5e6; d *= 1000) {
        const Setup s = frontWall(d);
        rows.push_back(
            {"eye distance " + sci(d) + " m", "px @1024", worstPixelError<float>(s), worstPixelError<double>(s), 1e-6});
    }
    return rows;
}

std::vector<StabilityRow> worldOffsetCases() {
    std::vector<StabilityRow> rows;
    for (double o = 1e3; o <= 1e7; o *= 100) {
        const Setup s = frontWall(1.2, glm::dvec3(o, -0.5 * o, o));
        rows.push_back(
            {"world offset " + sci(o) + " m", "px @1024", worstPixelError<float>(s), eyeRelativePixelError(s), 1e-3});
    }
    return rows;
}

std::vector<StabilityRow> depthOrderCases() {
    std::vector<StabilityRow> rows;
    const double near = 1e-3;
    for (double ratio : {1e3, 1e6, 1e9, std::numeric_limits<double>::infinity()}) {
        const double far = near * ratio;
        const FrustumT<double> f =
            offAxisFrustumT<double>({-1.5, 0, -1.5}, {1.5, 0, -1.5}, {-1.5, 3, -1.5}, {0, 1.5, 0.5}, near, far, 1e-3);
        const glm::mat4 p(f.clipFromView);
        auto reversed = [&](double z) {
            const glm::vec4 c = p * glm::vec4(0, 0, static_cast<float>(-z), 1);
            return c.z / c.w;
        };
        // Conventional OpenGL depth in [-1, 1] (far must be finite: use 1e9 * near for infinity).
        const double cf = std::isinf(far) ? 1e9 * near : far;
        const float a = static_cast<float>(-(cf + near) / (cf - near)),
                    b = static_cast<float>(-2 * cf * near / (cf - near));
        auto conventional = [&](double z) {
            const float zf = static_cast<float>(-z);
            return (a * zf + b) / -zf;
        };
        rows.push_back({"near/far ratio " + sci(ratio), "inversions", inversions(near, far, conventional),
                        inversions(near, far, reversed), 0.0});
    }
    return rows;
}

std::vector<StabilityRow> screenSizeCases() {
    std::vector<StabilityRow> rows;
    for (double size : {1e-3, 1e3}) {
        const Setup s{{0, 0, 0}, {size, 0, 0}, {0, size, 0}, {0.3 * size, 0.6 * size, 0.7 * size}, 1e-12};
        rows.push_back(
            {"screen " + sci(size) + " m", "px @1024", worstPixelError<float>(s), worstPixelError<double>(s), 1e-6});
    }
    return rows;
}

namespace {

// Worst pixel error (1024-px screen) of the float warp against the double warp, for points
// behind the wall seen by a CAVE front screen carried with an eye `distance` from the wall plane.
double floatWarpPixelError(double distance, double& condition) {
    const ScreenQuad wall{{-3, 0, -10}, {3, 0, -10}, {-3, 4, -10}};
    const glm::dvec3 eye{0.3, 1.6, -10.0 + distance}, shift = eye - glm::dvec3(0, 1.6, 0);
    const ScreenQuad screen{glm::dvec3(-1.5, 0, -1.5) + shift, glm::dvec3(1.5, 0, -1.5) + shift,
                            glm::dvec3(-1.5, 3, -1.5) + shift};
    const double inf = std::numeric_limits<double>::infinity();
    const OffAxisFrustum a = offAxisFrustum(wall, {0.5, 1.7, -4.0}, {0.05, inf});
    const glm::dmat4 warp = warpMatrix(a, wall, offAxisFrustum(screen, eye, {0.05, inf}).clipFromFrame(), 0.05);
    condition = warpCondition(warp);
    // As on the GPU: one float matrix, eye-relative float vertices.
    const glm::dmat4 full =
        warp * a.clipFromFrame() *
        glm::dmat4(glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(eye, 1));
    const glm::mat4 fullF(full);
    double worst = 0.0;
    for (double x = -2.5; x <= 2.5; x += 0.5)
        for (double y = 0.25; y <= 3.0; y += 0.5) {
            const glm::dvec3 p = glm::dvec3(x, y, -11.0) - eye;
            const glm::dvec4 ref = full * glm::dvec4(p, 1.0);
            const glm::vec4 f = fullF * glm::vec4(glm::vec3(p), 1.0f);
            if (ref.w <= 0.0) continue;
            const double e = std::max(std::abs(f.x / f.w - ref.x / ref.w), std::abs(f.y / f.w - ref.y / ref.w));
            worst = std::max(worst, std::isfinite(e) ? e * kPixels / 2 : std::numeric_limits<double>::infinity());
        }
    return worst;
}

}  // namespace

std::vector<StabilityRow> warpConditionCases() {
    std::vector<StabilityRow> rows;
    for (double d = 1.0; d >= 0.9e-6; d /= 10) {
        StabilityRow r{"warp, eye " + sci(d) + " m from wall plane", "px @1024", 0.0, 0.0, 0.5};
        r.floatError = floatWarpPixelError(d, r.condition);
        r.cavewallError = r.condition <= kMaxWarpCondition ? r.floatError : 0.0;
        rows.push_back(r);
    }
    return rows;
}

std::vector<StabilityRow> projectionStability() {
    std::vector<StabilityRow> all;
    for (auto* cases : {eyeDistanceCases, worldOffsetCases, depthOrderCases, screenSizeCases, warpConditionCases})
        for (StabilityRow& r : cases()) all.push_back(std::move(r));
    return all;
}

}  // namespace cavewall::display
