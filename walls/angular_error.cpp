#include "walls/angular_error.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <optional>
#include <queue>
#include <vector>

// Why the characterisation in angular_error.h holds: take Q off the line AB and the plane
// through A, B and Q. In it, the circle through A and B with centre c+ on Q's side at height
// rho = |AB| / (2 tan t) above the chord has radius R = |AB| / (2 sin t); by the inscribed angle
// theorem Q sees AB at more than t exactly when Q is inside that circle. Rotating the plane
// about AB sweeps c+ over the circle C of the header, and the point of C nearest Q is c+. So
// "angle > t somewhere on the rectangle" <=> min over C of dist(c, rectangle) < R. dist to a
// convex set D is convex with a unit gradient g, and c(phi + e) - c(phi) =
// (c(phi) - mid)(cos e - 1) + c'(phi) sin e, so by convexity
//   D(c(phi + e)) >= D(c(phi)) - |g . c'(phi)| sin|e| - rho (1 - cos e),
// a rigorous lower bound over an interval that is quadratic near the minimum: the 1D branch
// and bound converges fast even when the minimum is within 1e-9 of R.

namespace cavewall::walls {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kHalfPi = 0.5 * kPi;

// The wall rectangle with its lower-left corner at the origin (callers subtract it first, so
// far-away worlds keep their precision).
struct WallRect {
    glm::dvec3 right, up, normal;
    double width, height;
};

WallRect rectOf(const ScreenQuad& q) {
    const display::ScreenBasis b = display::screenBasis(q);
    return {b.right, b.up, b.normal, b.width, b.height};
}

glm::dvec3 rectPoint(const WallRect& r, double s, double t) { return s * r.right + t * r.up; }

glm::dvec3 nearestOnRect(const WallRect& r, glm::dvec3 p) {
    return rectPoint(r, std::clamp(glm::dot(p, r.right), 0.0, r.width), std::clamp(glm::dot(p, r.up), 0.0, r.height));
}

double angleBetween(glm::dvec3 a, glm::dvec3 b) { return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)); }

// The angle segment [a, b] subtends at q.
double subtended(glm::dvec3 q, glm::dvec3 a, glm::dvec3 b) { return angleBetween(a - q, b - q); }

bool finite(glm::dvec3 v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

enum class Decision { Below, Above, Unknown };

struct Witness {
    Decision decision = Decision::Unknown;
    glm::dvec3 point{0.0};  // for Above: a rectangle point seeing [a, b] at more than t
};

// The branch and bound below splits the circle into kStart intervals, then halves them; an
// interval at level k has half-width kPi / kStart / 2^k. Its centre's cosine and sine are carried
// down by the angle-addition formulas with these tabulated values, not recomputed: the planner
// spends most of its time here, and the rounding this adds (a few ulps per level) is far below
// decide()'s eps of 1e-12 of the scene's size.
constexpr int kStart = 32;
constexpr int kLevels = 64;  // half-widths down to kPi / 32 / 2^63, below decide()'s 1e-15 floor

struct HalfTable {
    double half[kLevels], sinHalf[kLevels], cosHalf[kLevels];
    double startCos[kStart], startSin[kStart];
    HalfTable() {
        for (int k = 0; k < kLevels; ++k) {
            half[k] = kPi / kStart / std::ldexp(1.0, k);
            sinHalf[k] = std::sin(half[k]);
            cosHalf[k] = std::cos(half[k]);
        }
        for (int i = 0; i < kStart; ++i) {
            startCos[i] = std::cos((i + 0.5) * 2 * kPi / kStart);
            startSin[i] = std::sin((i + 0.5) * 2 * kPi / kStart);
        }
    }
};

const HalfTable& halfTable() {
    static const HalfTable table;
    return table;
}

// Is the angle [a, b] subtends at every point of the rectangle at most t (t in (0, pi/2])?
Witness decide(const WallRect& r, glm::dvec3 a, glm::dvec3 b, double t) {
    const double len = glm::length(b - a);
    if (len <= 1e-300) return {Decision::Below, {}};
    const glm::dvec3 axis = (b - a) / len, mid = 0.5 * (a + b);
    const glm::dvec3 helper = std::abs(axis.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
    const glm::dvec3 m1 = glm::normalize(glm::cross(axis, helper)), m2 = glm::cross(axis, m1);
    const double radius = len / (2.0 * std::sin(t));
    const double rho = t >= kHalfPi ? 0.0 : len / (2.0 * std::tan(t));
    const double eps = 1e-12 * (radius + glm::length(mid) + r.width + r.height);
    const HalfTable& table = halfTable();
    struct Interval {
        double cs, sn;
        int level;
    };  // cos and sin of the centre; half = table.half[level]
    // Depth first: each level down adds one entry net, so kStart + kLevels entries suffice (a
    // fixed array: the planner calls this millions of times).
    std::array<Interval, kStart + kLevels> stack;
    int top = 0;
    for (int i = 0; i < kStart; ++i) stack[top++] = {table.startCos[i], table.startSin[i], 0};
    int budget = 200000;
    bool unknown = false;
    while (top > 0) {
        const Interval iv = stack[--top];
        const double cs = iv.cs, sn = iv.sn;
        const glm::dvec3 c = mid + rho * (cs * m1 + sn * m2);
        const glm::dvec3 q = nearestOnRect(r, c);
        const double dist = glm::length(c - q);
        if (dist < radius - eps) return {Decision::Above, q};
        // Lower bound over the interval from convexity of the distance (see the top comment).
        const double slope = glm::dot(c - q, rho * (cs * m2 - sn * m1)) / dist;
        const double lower = dist - std::abs(slope) * table.sinHalf[iv.level] - rho * (1 - table.cosHalf[iv.level]);
        if (lower > radius + eps) continue;
        if (--budget <= 0 || iv.level + 1 >= kLevels || table.half[iv.level] < 1e-15 || rho == 0.0) {
            unknown = true;
            continue;
        }
        // The children's centres lie half a child width either side: centre -+ half[level + 1].
        const int k = iv.level + 1;
        const double ch = table.cosHalf[k], sh = table.sinHalf[k];
        assert(top + 2 <= int(stack.size()));
        stack[top++] = {cs * ch + sn * sh, sn * ch - cs * sh, k};
        stack[top++] = {cs * ch - sn * sh, sn * ch + cs * sh, k};
    }
    return {unknown ? Decision::Unknown : Decision::Below, {}};
}

// A good lower bound: the best point of a grid, refined by pattern search.
double sampledMaximum(const WallRect& r, glm::dvec3 a, glm::dvec3 b) {
    constexpr int kGrid = 8;
    double best = -1, bs = 0, bt = 0;
    for (int i = 0; i <= kGrid; ++i)
        for (int j = 0; j <= kGrid; ++j) {
            const double s = r.width * i / kGrid, t = r.height * j / kGrid;
            const double v = subtended(rectPoint(r, s, t), a, b);
            if (v > best) {
                best = v;
                bs = s;
                bt = t;
            }
        }
    double step = std::max(r.width, r.height) / kGrid;
    while (step > 1e-9 * (1.0 + std::max(r.width, r.height))) {
        bool moved = false;
        const double ds[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};
        for (const auto& d : ds) {
            const double s = std::clamp(bs + d[0] * step, 0.0, r.width),
                         t = std::clamp(bt + d[1] * step, 0.0, r.height);
            const double v = subtended(rectPoint(r, s, t), a, b);
            if (v > best) {
                best = v;
                bs = s;
                bt = t;
                moved = true;
            }
        }
        if (!moved) step *= 0.5;
    }
    return best;
}

// First-order branch and bound over the rectangle, used only when the error reaches 90°,
// where the circle characterisation no longer applies. Returns an upper bound (<= pi).
double boundAbove90(const WallRect& r, glm::dvec3 a, glm::dvec3 b, double lower) {
    struct Cell {
        double s, t, hs, ht, bound;
    };
    auto bound = [&](double s, double t, double hs, double ht) {
        const glm::dvec3 q = rectPoint(r, s, t);
        const double reach = std::hypot(hs, ht);
        const double da = std::max(std::abs(glm::dot(a, r.normal)), glm::length(a - q) - reach);
        const double db = std::max(std::abs(glm::dot(b, r.normal)), glm::length(b - q) - reach);
        if (da <= 0 || db <= 0) return kPi;
        return std::min(kPi, subtended(q, a, b) + reach * (1 / da + 1 / db));
    };
    auto cmp = [](const Cell& x, const Cell& y) { return x.bound < y.bound; };
    std::priority_queue<Cell, std::vector<Cell>, decltype(cmp)> queue(cmp);
    const double hs = 0.5 * r.width, ht = 0.5 * r.height;
    queue.push({hs, ht, hs, ht, bound(hs, ht, hs, ht)});
    for (int budget = 20000; budget > 0 && !queue.empty(); --budget) {
        const Cell c = queue.top();
        if (c.bound - lower <= 1e-6) break;
        queue.pop();
        lower = std::max(lower, subtended(rectPoint(r, c.s, c.t), a, b));
        for (int i = 0; i < 4; ++i) {
            const double s = c.s + (i & 1 ? 0.5 : -0.5) * c.hs, t = c.t + (i & 2 ? 0.5 : -0.5) * c.ht;
            queue.push({s, t, 0.5 * c.hs, 0.5 * c.ht, bound(s, t, 0.5 * c.hs, 0.5 * c.ht)});
        }
    }
    return queue.empty() ? lower : std::max(lower, queue.top().bound);
}

// The maximum over the rectangle of the angle [a, b] subtends (a proven upper bound within
// kErrorTolerance of it).
double maxSubtended(const WallRect& r, glm::dvec3 a, glm::dvec3 b) {
    if (glm::length(b - a) <= 1e-300) return 0.0;
    double lower = sampledMaximum(r, a, b);
    if (lower >= kHalfPi || decide(r, a, b, kHalfPi).decision != Decision::Below) return boundAbove90(r, a, b, lower);
    double upper = kHalfPi;
    // Usually the refined sample is the maximum and one decision proves it.
    const double first = std::min(upper, lower + kErrorTolerance);
    if (decide(r, a, b, first).decision == Decision::Below) return first;
    while (upper - lower > kErrorTolerance) {
        const double t = 0.5 * (lower + upper);
        const Witness w = decide(r, a, b, t);
        if (w.decision == Decision::Below)
            upper = t;
        else
            lower = std::max(t, w.decision == Decision::Above ? subtended(w.point, a, b) : t);
    }
    return upper;
}

// The point M whose segment [eye, M] subtends the finite-depth error (header).
glm::dvec3 depthPoint(glm::dvec3 eye, glm::dvec3 sampling, const WallRect& r, double depth) {
    const double h = std::abs(glm::dot(sampling, r.normal));
    if (!std::isfinite(depth) || h < 1e-12) return sampling;
    const double k = depth / h;
    return (eye + k * sampling) / (1.0 + k);
}

}  // namespace

double pointError(glm::dvec3 eye, glm::dvec3 samplingPoint, glm::dvec3 scenePoint, const ScreenQuad& wall) {
    const glm::dvec3 n = display::screenBasis(wall).normal;
    const double denom = glm::dot(scenePoint - samplingPoint, n);
    if (std::abs(denom) < 1e-15) return 0.0;
    const double t = glm::dot(wall.lowerLeft - samplingPoint, n) / denom;
    const glm::dvec3 q = samplingPoint + t * (scenePoint - samplingPoint);
    return angleBetween(scenePoint - eye, q - eye);
}

double maxAngularError(glm::dvec3 eye, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind) {
    if (!finite(eye) || !finite(samplingPoint) || std::isnan(depthBehind)) return kPi;
    if (depthBehind <= 0) return 0.0;
    const WallRect r = rectOf(wall);
    const glm::dvec3 e = eye - wall.lowerLeft, s = samplingPoint - wall.lowerLeft;
    return maxSubtended(r, e, depthPoint(e, s, r, depthBehind));
}

namespace {

// errorWithin with the wall's rectangle r = rectOf(wall) computed by the caller.
bool errorWithinRect(const WallRect& r, glm::dvec3 eye, glm::dvec3 samplingPoint, const ScreenQuad& wall,
                     double depthBehind, double alpha) {
    if (!finite(eye) || !finite(samplingPoint) || !(alpha > 0) || std::isnan(depthBehind)) return false;
    if (depthBehind <= 0) return true;
    const glm::dvec3 e = eye - wall.lowerLeft, s = samplingPoint - wall.lowerLeft;
    return decide(r, e, depthPoint(e, s, r, depthBehind), std::min(alpha, kHalfPi)).decision == Decision::Below;
}

}  // namespace

bool errorWithin(glm::dvec3 eye, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind, double alpha) {
    return errorWithinRect(rectOf(wall), eye, samplingPoint, wall, depthBehind, alpha);
}

namespace {

// Branch and bound over the zone's bounding box for a finite depth (header).
double refineFiniteDepth(const ZoneVolume& zone, glm::dvec3 s, const ScreenQuad& wall, double depth, double upper,
                         double tolerance, int budget) {
    const display::ScreenBasis b = display::screenBasis(wall);
    // The segment [Q, P] a texel stands for has length k |Q - S|, k = depth / dist(S, plane);
    // [Q, P] subtends an angle whose gradient in the eye is |QP| / (|EQ| |EP|) (law of cosines
    // on the two perpendicular unit vectors), and |EQ| >= h, |EP| >= h + depth.
    const glm::dvec3 right = wall.lowerRight - wall.lowerLeft, up = wall.upperLeft - wall.lowerLeft;
    double farthest = 0.0;
    for (const glm::dvec3& q : {wall.lowerLeft, wall.lowerRight, wall.upperLeft, wall.lowerLeft + right + up})
        farthest = std::max(farthest, glm::length(q - s));
    const double hs = std::abs(glm::dot(s - wall.lowerLeft, b.normal));
    if (hs < 1e-12) return upper;
    const double slope = depth / hs * farthest;
    struct Box {
        glm::dvec3 lo, hi;
        double bound;
    };
    double lower = 0.0;
    // Bound over box ∩ zone from one eye inside it; nullopt when the box misses the zone.
    auto evaluate = [&](glm::dvec3 lo, glm::dvec3 hi) -> std::optional<Box> {
        const Polygon2 part = clipBox(zone.floor, {lo.x, lo.z}, {hi.x, hi.z});
        if (part.empty()) return std::nullopt;
        double h = kInfiniteDepth;
        for (int i = 0; i < 8; ++i)
            h = std::min(
                h, glm::dot(glm::dvec3(i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z) - wall.lowerLeft,
                            b.normal));
        const glm::dvec2 c = centroid(part);
        const double v = maxAngularError({c.x, 0.5 * (lo.y + hi.y), c.y}, s, wall, depth);
        lower = std::max(lower, v);
        const double reach = glm::length(hi - lo);
        return Box{lo, hi, h <= 0 ? upper : std::min(upper, v + reach * slope / (h * (h + depth)))};
    };
    for (const glm::dvec2& p : zone.floor)
        for (double y : {zone.heightRange.x, zone.heightRange.y})
            lower = std::max(lower, maxAngularError({p.x, y, p.y}, s, wall, depth));
    glm::dvec3 lo(kInfiniteDepth), hi(-kInfiniteDepth);
    for (const glm::dvec2& p : zone.floor) {
        lo = glm::min(lo, {p.x, zone.heightRange.x, p.y});
        hi = glm::max(hi, {p.x, zone.heightRange.y, p.y});
    }
    auto cmp = [](const Box& x, const Box& y) { return x.bound < y.bound; };
    std::priority_queue<Box, std::vector<Box>, decltype(cmp)> queue(cmp);
    if (auto box = evaluate(lo, hi)) queue.push(*box);
    while (!queue.empty() && queue.top().bound - lower > tolerance && budget-- > 0) {
        const Box box = queue.top();
        queue.pop();
        const glm::dvec3 size = box.hi - box.lo;
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : size.y >= size.z ? 1 : 2;
        glm::dvec3 mid = box.hi;
        mid[axis] = 0.5 * (box.lo[axis] + box.hi[axis]);
        glm::dvec3 midLo = box.lo;
        midLo[axis] = mid[axis];
        for (auto half : {evaluate(box.lo, mid), evaluate(midLo, box.hi)})
            if (half) queue.push(*half);
    }
    return queue.empty() ? lower : std::max(lower, queue.top().bound);
}

}  // namespace

double zoneMaxError(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind,
                    double tolerance, int budget) {
    if (depthBehind <= 0) return 0.0;
    double worst = 0.0;
    for (const glm::dvec2& p : zone.floor)
        for (double y : {zone.heightRange.x, zone.heightRange.y})
            worst = std::max(worst, maxAngularError({p.x, y, p.y}, samplingPoint, wall, kInfiniteDepth));
    // Above 90° the cones are no longer convex, so the vertices prove nothing.
    if (worst > kHalfPi) return kPi;
    if (!std::isfinite(depthBehind) || zone.floor.empty()) return worst;
    return refineFiniteDepth(zone, samplingPoint, wall, depthBehind, worst, tolerance, budget);
}

bool zoneWithin(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double alpha) {
    // The answer is the conjunction over the eyes, so their order does not change it; eyes far
    // from the sampling point for their distance to the wall usually fail first, and a zone
    // that fails (half of the planner's bisection probes) then costs one decision, not many.
    struct Eye {
        glm::dvec3 p;
        double score;
    };
    std::vector<Eye> eyes;
    eyes.reserve(2 * zone.floor.size());
    const WallRect r = rectOf(wall);
    for (const glm::dvec2& p : zone.floor)
        for (double y : {zone.heightRange.x, zone.heightRange.y}) {
            const glm::dvec3 e{p.x, y, p.y};
            const double h = std::abs(glm::dot(e - wall.lowerLeft, r.normal));
            eyes.push_back({e, glm::length(e - samplingPoint) / std::max(h, 1e-9)});
        }
    std::sort(eyes.begin(), eyes.end(), [](const Eye& a, const Eye& b) { return a.score > b.score; });
    for (const Eye& e : eyes)
        if (!errorWithinRect(r, e.p, samplingPoint, wall, kInfiniteDepth, alpha)) return false;
    return true;
}

namespace {

// The zone's vertices with the depth each is decided at (angular_error.h, zoneDepthBound); an
// empty list when some vertex's eta >= 1 or lies on the plane (the depth-independent bound then).
struct InflatedEye {
    glm::dvec3 eye;
    double depth;
};
std::vector<InflatedEye> inflatedEyes(const ZoneVolume& zone, const ScreenQuad& wall, double depthBehind) {
    const glm::dvec3 n = display::screenBasis(wall).normal;
    glm::dvec2 mean(0.0);
    for (const glm::dvec2& p : zone.floor) mean += p;
    mean /= static_cast<double>(zone.floor.size());
    double r2 = 0.0;
    for (const glm::dvec2& p : zone.floor) r2 = std::max(r2, glm::dot(p - mean, p - mean));
    const double dy = zone.heightRange.y - zone.heightRange.x;
    r2 += 0.25 * dy * dy;
    std::vector<InflatedEye> eyes;
    for (const glm::dvec2& p : zone.floor)
        for (double y : {zone.heightRange.x, zone.heightRange.y}) {
            const glm::dvec3 e{p.x, y, p.y};
            const double h = std::abs(glm::dot(e - wall.lowerLeft, n));
            const double eta = r2 / (h * h);
            if (!(eta < 1.0)) return {};
            eyes.push_back({e, depthBehind / (1.0 - eta)});
        }
    return eyes;
}

}  // namespace

double zoneDepthBound(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind) {
    if (depthBehind <= 0) return 0.0;
    const double independent = zoneMaxError(zone, samplingPoint, wall, kInfiniteDepth);
    if (!std::isfinite(depthBehind) || zone.floor.empty() || independent > kHalfPi) return independent;
    double worst = 0.0;
    const std::vector<InflatedEye> eyes = inflatedEyes(zone, wall, depthBehind);
    if (eyes.empty()) return independent;
    for (const InflatedEye& e : eyes) worst = std::max(worst, maxAngularError(e.eye, samplingPoint, wall, e.depth));
    // The form needs t < 90°: a larger vertex error proves nothing. (At most the independent
    // bound anyway: each vertex's error grows with the depth.)
    return worst < kHalfPi ? std::min(worst, independent) : independent;
}

bool zoneWithinDepth(const ZoneVolume& zone, glm::dvec3 samplingPoint, const ScreenQuad& wall, double depthBehind,
                     double alpha) {
    if (!(alpha > 0)) return false;
    if (depthBehind <= 0) return true;
    if (!std::isfinite(depthBehind) || zone.floor.empty()) return zoneWithin(zone, samplingPoint, wall, alpha);
    const std::vector<InflatedEye> eyes = inflatedEyes(zone, wall, depthBehind);
    if (eyes.empty() || !(alpha < kHalfPi)) return zoneWithin(zone, samplingPoint, wall, alpha);
    const WallRect r = rectOf(wall);
    // A vertex over alpha at its depth is over it at every larger depth: zoneWithin would fail too.
    for (const InflatedEye& e : eyes)
        if (!errorWithinRect(r, e.eye, samplingPoint, wall, e.depth, alpha)) return false;
    return true;
}

double seedError2D(double halfWidth, double distance) { return std::atan(halfWidth / distance); }

double seedMinDistance(double halfWidth, double alpha) { return halfWidth / std::tan(alpha); }

int seedTextureCount(double sceneWidth, double minDistance, double alpha) {
    const double halfWidth = minDistance * std::tan(alpha);
    return int(std::ceil(sceneWidth / (2.0 * halfWidth) - 1e-9));
}

}  // namespace cavewall::walls
