#include "display/display_summary.h"

#include "config/display_limits.h"
#include "config/json_reader.h"
#include "display/pixel_scale.h"
#include "display/stereo.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

namespace cavewall::display {

namespace {

using config::formatNumber;

std::string vec(const glm::dvec3& v) {
    // Rounded to 0.1 mm, and -0 printed as 0: a normal reads [0, 0, 1], not [-0, 0, 1].
    const auto c = [](double x) { return formatNumber(std::round(x * 1e4) / 1e4 + 0.0); };
    return "[" + c(v.x) + ", " + c(v.y) + ", " + c(v.z) + "]";
}

// Sutherland-Hodgman: the part of convex polygon `poly` (2D) where dot(p, n) <= d.
std::vector<glm::dvec2> clipHalfPlane(const std::vector<glm::dvec2>& poly, glm::dvec2 n, double d) {
    std::vector<glm::dvec2> out;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        const double sp = glm::dot(p, n) - d, sq = glm::dot(q, n) - d;
        if (sp <= 0.0) out.push_back(p);
        if ((sp < 0.0 && sq > 0.0) || (sp > 0.0 && sq < 0.0)) out.push_back(p + (q - p) * (sp / (sp - sq)));
    }
    return out;
}

double polygonArea(const std::vector<glm::dvec2>& poly) {
    double twice = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i) {
        const glm::dvec2 p = poly[i], q = poly[(i + 1) % poly.size()];
        twice += p.x * q.y - q.x * p.y;
    }
    return std::abs(twice) / 2.0;
}

// The overlap of `a` and `b` when they lie in one plane: b's outline in a's (right, up) frame
// clipped to a's rectangle.
std::vector<glm::dvec3> coplanarOverlap(const ScreenFacts& a, const ScreenFacts& b, double tolerance) {
    const ScreenBasis& f = a.basis;
    if (std::abs(glm::dot(f.normal, b.basis.normal)) < 1.0 - 1e-9) return {};
    if (std::abs(glm::dot(f.normal, b.centre - a.centre)) > tolerance) return {};
    std::vector<glm::dvec2> poly;
    for (const glm::dvec3& p : outline(b))
        poly.push_back({glm::dot(p - a.quad.lowerLeft, f.right), glm::dot(p - a.quad.lowerLeft, f.up)});
    poly = clipHalfPlane(poly, {-1, 0}, 0.0);
    poly = clipHalfPlane(poly, {1, 0}, f.width);
    poly = clipHalfPlane(poly, {0, -1}, 0.0);
    poly = clipHalfPlane(poly, {0, 1}, f.height);
    if (poly.size() < 3 || polygonArea(poly) <= tolerance * tolerance) return {};
    std::vector<glm::dvec3> out;
    for (const glm::dvec2& p : poly) out.push_back(a.quad.lowerLeft + p.x * f.right + p.y * f.up);
    return out;
}

// The common part of segments [p0, p1] and [q0, q1] when they lie on one line.
std::optional<std::pair<glm::dvec3, glm::dvec3>> commonSegment(glm::dvec3 p0, glm::dvec3 p1, glm::dvec3 q0,
                                                               glm::dvec3 q1, double tolerance) {
    const double length = glm::length(p1 - p0);
    const glm::dvec3 dir = (p1 - p0) / length;
    const auto offLine = [&](glm::dvec3 q) { return glm::length(glm::cross(q - p0, dir)); };
    if (offLine(q0) > tolerance || offLine(q1) > tolerance) return std::nullopt;
    const double t0 = glm::dot(q0 - p0, dir), t1 = glm::dot(q1 - p0, dir);
    const double lo = std::max(0.0, std::min(t0, t1)), hi = std::min(length, std::max(t0, t1));
    if (hi - lo <= tolerance) return std::nullopt;
    return std::pair{p0 + lo * dir, p0 + hi * dir};
}

void printScreens(std::ostream& out, const std::vector<ScreenFacts>& screens) {
    std::size_t nameWidth = 6;
    for (const ScreenFacts& s : screens) nameWidth = std::max(nameWidth, s.name.size());
    const auto pad = [](std::string text, std::size_t width) {
        return text.size() < width ? text + std::string(width - text.size(), ' ') : text;
    };
    out << "  " << pad("screen", nameWidth) << "  " << pad("size (m)", 13) << "  " << pad("pixels", 11) << "  "
        << pad("normal (front side)", 24) << "  pixels/degree\n";
    for (const ScreenFacts& s : screens)
        out << "  " << pad(s.name, nameWidth) << "  "
            << pad(config::formatFixed(s.basis.width, 2) + " x " + config::formatFixed(s.basis.height, 2), 13) << "  "
            << pad(std::to_string(s.resolution.x) + " x " + std::to_string(s.resolution.y), 11) << "  "
            << pad(vec(s.basis.normal), 24) << "  " << config::formatFixed(s.pixelsPerDegree, 1) << "\n";
}

void printViewer(std::ostream& out, const config::DisplayConfig& c) {
    const config::Viewer& v = c.viewer;
    out << "default head " << vec(v.headPosition) << " m";
    if (c.stereo != config::StereoMode::Mono) {
        out << ", eyes " << formatNumber(v.eyeSeparation * 1000.0) << " mm apart: left "
            << vec(eyePosition(v.headPosition, v.headOrientation, v.eyeSeparation, Eye::Left)) << ", right "
            << vec(eyePosition(v.headPosition, v.headOrientation, v.eyeSeparation, Eye::Right));
    }
    out << "\n";
}

void printTracking(std::ostream& out, const config::DisplayConfig& c) {
    const glm::dmat4& m = c.tracking.caveFromTracker;
    out << "tracking: caveFromTracker ";
    if (m == glm::dmat4(1.0)) {
        out << "identity";
    } else {
        for (int row = 0; row < 3; ++row)
            out << (row ? ", " : "[") << "[" << formatNumber(m[0][row]) << ", " << formatNumber(m[1][row]) << ", "
                << formatNumber(m[2][row]) << ", " << formatNumber(m[3][row]) << "]";
        out << ", [0, 0, 0, 1]]";
    }
    const config::TrackingVolume volume = config::trackingVolumeOf(c);
    out << ", latency " << formatNumber(c.tracking.latencyMs) << " ms, volume " << vec(volume.min) << " to "
        << vec(volume.max) << " m" << (c.tracking.volume ? "" : " (default: screens and head grown by 2 m)") << "\n";
}

}  // namespace

std::vector<glm::dvec3> outline(const ScreenFacts& s) {
    return {s.quad.lowerLeft, s.quad.lowerRight, s.upperRight, s.quad.upperLeft};
}

std::vector<ScreenFacts> screenFacts(const config::DisplayConfig& config) {
    std::vector<ScreenFacts> out;
    for (const config::Screen& s : config.screens) {
        ScreenFacts f;
        f.name = s.name;
        f.quad = {s.lowerLeft, s.lowerRight, s.upperLeft};
        f.upperRight = s.lowerRight + s.upperLeft - s.lowerLeft;
        f.centre = (s.lowerRight + s.upperLeft) / 2.0;
        f.basis = screenBasis(f.quad);
        f.resolution = s.resolution;
        f.pixelsPerDegree = minPixelsPerDegree(viewScreen(f.quad, config.viewer.headPosition, s.resolution));
        out.push_back(std::move(f));
    }
    return out;
}

std::vector<SharedEdge> sharedEdges(const std::vector<ScreenFacts>& screens, double tolerance) {
    std::vector<SharedEdge> out;
    for (std::size_t a = 0; a < screens.size(); ++a)
        for (std::size_t b = a + 1; b < screens.size(); ++b) {
            const std::vector<glm::dvec3> p = outline(screens[a]), q = outline(screens[b]);
            for (std::size_t i = 0; i < 4; ++i)
                for (std::size_t j = 0; j < 4; ++j)
                    if (auto s = commonSegment(p[i], p[(i + 1) % 4], q[j], q[(j + 1) % 4], tolerance))
                        out.push_back({static_cast<int>(a), static_cast<int>(b), s->first, s->second});
        }
    return out;
}

std::vector<ScreenOverlap> screenOverlaps(const std::vector<ScreenFacts>& screens, double tolerance) {
    std::vector<ScreenOverlap> out;
    for (std::size_t a = 0; a < screens.size(); ++a)
        for (std::size_t b = a + 1; b < screens.size(); ++b) {
            std::vector<glm::dvec3> polygon = coplanarOverlap(screens[a], screens[b], tolerance);
            if (polygon.empty()) continue;
            std::vector<glm::dvec2> flat;
            for (const glm::dvec3& p : polygon)
                flat.push_back({glm::dot(p, screens[a].basis.right), glm::dot(p, screens[a].basis.up)});
            out.push_back({static_cast<int>(a), static_cast<int>(b), std::move(polygon), polygonArea(flat)});
        }
    return out;
}

void printDisplaySummary(std::ostream& out, const config::DisplayConfig& c, const std::string& source) {
    const std::vector<ScreenFacts> screens = screenFacts(c);
    out << "display '" << c.name << "' (" << source << "): " << screens.size() << " screens, stereo "
        << config::toString(c.stereo) << ", near " << formatNumber(c.viewer.near) << " m, far "
        << (std::isinf(c.viewer.far) ? std::string("infinite") : formatNumber(c.viewer.far) + " m") << "\n";
    printScreens(out, screens);
    out << "  (pixels/degree: the fewest anywhere on the screen, seen from the default head)\n";
    printViewer(out, c);
    printTracking(out, c);
    for (const SharedEdge& e : sharedEdges(screens))
        out << "shared edge: " << screens[e.a].name << " and " << screens[e.b].name << ", " << vec(e.from) << " to "
            << vec(e.to) << "\n";
    for (const ScreenOverlap& o : screenOverlaps(screens))
        out << "overlap: " << screens[o.a].name << " and " << screens[o.b].name << " cover the same "
            << config::formatFixed(o.area, 3) << " m² (expected screens side by side, not on top of each other)\n";
}

}  // namespace cavewall::display
