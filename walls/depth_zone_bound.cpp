// The depth walls' error bounds over an eye, a zone and a zone's segment (depth_wall.h): the
// search over boxes of eyes and depth spans that planning asks.
#include "walls/depth_wall.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

namespace cavewall::walls {

namespace {

constexpr double kPi = 3.14159265358979323846;

// The span widened for the depths' float rounding (depth_wall.h, "Precision").
glm::dvec2 widened(glm::dvec2 span, double ds) {
    const double lo = std::max(0.0, span.x - 1e-6 * (ds + span.x));
    return {lo, std::isfinite(span.y) ? span.y + 1e-6 * (ds + span.y) : span.y};
}

}  // namespace

double depthEyeBound(glm::dvec3 eye, glm::dvec3 samplingPoint, const display::ScreenQuad& wall, glm::dvec2 span,
                     double texelDiagonal) {
    return depthZoneBound({{glm::dvec2(eye.x, eye.z)}, {eye.y, eye.y}}, samplingPoint, wall, span, texelDiagonal);
}

namespace {

// depthZoneBound's search. With a finite `alpha` it stops as soon as the answer to "bound <=
// alpha?" is known, and then returns a value on the same side of alpha as the bound: the largest
// box bound only falls as boxes split (|v| over a sub-box is at most over the box, its gap to the
// eyes at least as large), so once it is within alpha the finished bound is too; and every
// centre estimate is at most the bound of any box holding that centre (kdiff(D) / D decreases,
// kdiff <= kdMax, the distance to the eye is at least both D and the box's far), so once an
// estimate exceeds alpha the finished bound does too. NaN: the whole search.
double depthZoneSearch(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                       glm::dvec2 span, double texelDiagonal, double alpha) {
    const WallFrame f = wallFrame(wall);
    const glm::dvec3 s = f.toWall(samplingPoint);
    const double ds = std::abs(s.z);
    if (!(ds > 0.0) || zone.floor.empty() || !(span.x >= 0.0) || std::isnan(span.y) || !(texelDiagonal >= 0.0))
        return kPi;
    // The eyes (zone vertices) in the wall frame: lateral x, y and the distance D_E as z.
    std::vector<glm::dvec3> eyes;
    double dmin = std::numeric_limits<double>::infinity(), dmax = 0.0;
    glm::dvec2 eyeLo(std::numeric_limits<double>::infinity()), eyeHi = -eyeLo;
    for (const glm::dvec2& p : zone.floor)
        for (double y : {zone.heightRange.x, zone.heightRange.y}) {
            const glm::dvec3 e = f.toWall({p.x, y, p.y});
            if (!(e.z * s.z > 0.0)) return kPi;  // on the plane or the other side
            eyes.push_back({e.x, e.y, std::abs(e.z)});
            dmin = std::min(dmin, std::abs(e.z));
            dmax = std::max(dmax, std::abs(e.z));
            eyeLo = glm::min(eyeLo, glm::dvec2(e));
            eyeHi = glm::max(eyeHi, glm::dvec2(e));
        }
    const double texel = 0.5 * texelDiagonal * std::max(1.0 / dmin, 1.0 / ds);
    const glm::dvec2 sp = widened(span, ds);
    if (!(sp.y > sp.x)) return std::min(texel, kPi);
    // k(dFar) - k(dNear) = D (dFar - dNear) / ((D + dFar)(D + dNear)) over D in [dmin, dmax]:
    // unimodal with its peak at sqrt(dFar dNear) (increasing when dFar is infinite).
    auto kdiff = [&](double d) {
        return std::isfinite(sp.y) ? d * (sp.y - sp.x) / ((d + sp.y) * (d + sp.x)) : d / (d + sp.x);
    };
    const double kdMax = kdiff(std::isfinite(sp.y) ? std::clamp(std::sqrt(sp.x * sp.y), dmin, dmax) : dmax);
    const double kFar = std::isfinite(sp.y) ? sp.y / (dmin + sp.y) : 1.0;  // k(dFar) at its largest
    const double reach = 0.5 * texelDiagonal * std::max(1.0, dmax / ds);
    const glm::dvec2 sl(s);
    auto parallax = [&](const glm::dvec3& e, glm::dvec2 t) {
        return glm::length((glm::dvec2(e) - sl) + (e.z / ds - 1.0) * (t - sl));
    };
    // A box of texel centres: an upper bound of (k(dFar) - k(dNear)) |v| / distance over every
    // eye of the zone (the header's refinement: the segment lies within R of T_c).
    struct Box {
        glm::dvec2 lo, hi;
        double upper;
    };
    auto upperOf = [&](glm::dvec2 lo, glm::dvec2 hi) {
        double v = 0.0;
        for (const glm::dvec3& e : eyes)
            for (glm::dvec2 c : {lo, hi, glm::dvec2(lo.x, hi.y), glm::dvec2(hi.x, lo.y)})
                v = std::max(v, parallax(e, c));
        const glm::dvec2 gap = glm::max(glm::dvec2(0.0), glm::max(lo - eyeHi, eyeLo - hi));
        // kdiff(D) / max(D, far) <= min(kdiff(dmin) / dmin, kdMax / far): kdiff(D) / D decreases.
        const double far = std::sqrt(dmin * dmin + glm::dot(gap, gap)) - (reach + kFar * v);
        const double near = kdiff(dmin) / dmin;
        return Box{lo, hi, v * (far > dmin ? std::min(near, kdMax / far) : near)};
    };
    // An estimate (not a bound) at a box's centre, to stop refining boxes that cannot matter.
    auto estimate = [&](glm::dvec2 c) {
        double best = 0.0;
        for (const glm::dvec3& e : eyes)
            best = std::max(best, kdiff(e.z) * parallax(e, c) /
                                      std::sqrt(e.z * e.z + glm::dot(glm::dvec2(e) - c, glm::dvec2(e) - c)));
        return best;
    };
    auto lower = [](const Box& a, const Box& b) { return a.upper < b.upper; };
    std::vector<Box> heap{upperOf({0.0, 0.0}, {f.width, f.height})};
    double found = 0.0;
    for (int budget = 64; budget > 0; --budget) {
        const Box top = heap.front();
        if (top.upper <= found * 1.02 + 1e-4) break;
        if (top.upper + texel <= alpha) return top.upper + texel;
        if (found + texel > alpha) return found + texel;
        std::pop_heap(heap.begin(), heap.end(), lower);
        heap.pop_back();
        const glm::dvec2 mid = 0.5 * (top.lo + top.hi);
        found = std::max(found, estimate(mid));
        for (const Box& b : {upperOf(top.lo, mid), upperOf({mid.x, top.lo.y}, {top.hi.x, mid.y}),
                             upperOf({top.lo.x, mid.y}, {mid.x, top.hi.y}), upperOf(mid, top.hi)}) {
            heap.push_back(b);
            std::push_heap(heap.begin(), heap.end(), lower);
        }
    }
    const double bound = heap.front().upper + texel;
    return std::isfinite(bound) ? std::min(bound, kPi) : kPi;
}

}  // namespace

double depthZoneBound(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                      glm::dvec2 span, double texelDiagonal) {
    return depthZoneSearch(zone, samplingPoint, wall, span, texelDiagonal, std::numeric_limits<double>::quiet_NaN());
}

bool depthZoneWithin(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall, glm::dvec2 span,
                     double texelDiagonal, double alpha) {
    return alpha > 0.0 && depthZoneSearch(zone, samplingPoint, wall, span, texelDiagonal, alpha) <= alpha;
}

display::ScreenQuad nearWall(const display::ScreenQuad& wall, glm::dvec3 samplingPoint, double depth) {
    const double ds = std::abs(glm::dot(samplingPoint - wall.lowerLeft, display::screenBasis(wall).normal));
    if (!(ds > 0.0))
        throw Error("nearWall: the sampling point is on the wall's plane (expected a distance > 0, got 0)");
    const double a = depth / ds;
    auto moved = [&](glm::dvec3 c) { return c + a * (c - samplingPoint); };
    return {moved(wall.lowerLeft), moved(wall.lowerRight), moved(wall.upperLeft)};
}

double depthSegmentEyeBound(glm::dvec3 eye, glm::dvec3 samplingPoint, const display::ScreenQuad& wall, glm::dvec2 span,
                            double texelDiagonal) {
    const WallFrame f = wallFrame(wall);
    const glm::dvec3 e = f.toWall(eye), s = f.toWall(samplingPoint);
    if (!(e.z * s.z > 0.0) || !(texelDiagonal >= 0.0) || !(span.x >= 0.0) || std::isnan(span.y)) return kPi;
    const double de = std::abs(e.z), ds = std::abs(s.z);
    const glm::dvec2 sp = widened(span, ds);
    const double seg =
        sp.y > sp.x ? maxAngularError(eye, samplingPoint, nearWall(wall, samplingPoint, sp.x), sp.y - sp.x) : 0.0;
    const double bound = seg + 0.5 * texelDiagonal * std::max(1.0 / de, 1.0 / ds);
    return std::isfinite(bound) ? std::min(bound, kPi) : kPi;
}

namespace {

// What both zone forms of the segment bound need: the texel term over the zone, 0.5 h max(1 /
// Dmin, 1 / D_S), and the span widened for rounding (depth_wall.h, "Precision"); nullopt when
// the form does not apply (no zone, a negative texel, a near depth that is negative or infinite,
// a NaN far depth, an eye on the plane or on the other side).
struct SegmentZone {
    double texel;
    glm::dvec2 span;
};
std::optional<SegmentZone> segmentZone(const ZoneVolume& zone, glm::dvec3 samplingPoint,
                                       const display::ScreenQuad& wall, glm::dvec2 span, double texelDiagonal) {
    const WallFrame f = wallFrame(wall);
    const glm::dvec3 s = f.toWall(samplingPoint);
    if (zone.floor.empty() || !(texelDiagonal >= 0.0) || !(span.x >= 0.0) || !std::isfinite(span.x) ||
        std::isnan(span.y))
        return std::nullopt;
    double dmin = std::numeric_limits<double>::infinity();
    for (const glm::dvec2& p : zone.floor)
        for (double y : {zone.heightRange.x, zone.heightRange.y}) {
            const glm::dvec3 e = f.toWall({p.x, y, p.y});
            if (!(e.z * s.z > 0.0)) return std::nullopt;  // on the plane or the other side
            dmin = std::min(dmin, std::abs(e.z));
        }
    const double ds = std::abs(s.z);
    return SegmentZone{0.5 * texelDiagonal * std::max(1.0 / dmin, 1.0 / ds), widened(span, ds)};
}

}  // namespace

double depthSegmentZoneBound(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                             glm::dvec2 span, double texelDiagonal) {
    const std::optional<SegmentZone> z = segmentZone(zone, samplingPoint, wall, span, texelDiagonal);
    if (!z) return kPi;
    const glm::dvec2 sp = z->span;
    const double seg =
        sp.y > sp.x ? zoneDepthBound(zone, samplingPoint, nearWall(wall, samplingPoint, sp.x), sp.y - sp.x) : 0.0;
    const double bound = seg + z->texel;
    return std::isfinite(bound) ? std::min(bound, kPi) : kPi;
}

bool depthSegmentZoneWithin(const ZoneVolume& zone, glm::dvec3 samplingPoint, const display::ScreenQuad& wall,
                            glm::dvec2 span, double texelDiagonal, double alpha) {
    const std::optional<SegmentZone> z = segmentZone(zone, samplingPoint, wall, span, texelDiagonal);
    if (!z || !(alpha - z->texel > 0.0)) return false;
    const glm::dvec2 sp = z->span;
    return !(sp.y > sp.x) ||
           zoneWithinDepth(zone, samplingPoint, nearWall(wall, samplingPoint, sp.x), sp.y - sp.x, alpha - z->texel);
}

}  // namespace cavewall::walls
