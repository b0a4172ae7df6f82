#include "display/foldout.h"

#include "display/off_axis.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>

namespace cavewall::display {

namespace {

// Corners closer than this are the same point: configurations write shared corners with the
// same numbers, so only rounding has to be absorbed.
constexpr double kSharedCornerTolerance = 1e-6;  // metres

struct Placed {
    ScreenBasis basis;
    std::array<glm::dvec3, 4> corners;  // lowerLeft, lowerRight, upperRight, upperLeft
    glm::dmat4 unfold{1.0};             // rigid: cave frame -> position flat in the root plane
    bool placed = false;
};

std::array<glm::dvec3, 4> cornersOf(const config::Screen& s) {
    return {s.lowerLeft, s.lowerRight, s.lowerRight + s.upperLeft - s.lowerLeft, s.upperLeft};
}

// The two corners `a` shares with `b`, if they share an edge.
std::optional<std::array<glm::dvec3, 2>> sharedEdge(const Placed& a, const Placed& b) {
    std::vector<glm::dvec3> shared;
    for (const glm::dvec3& p : a.corners)
        for (const glm::dvec3& q : b.corners)
            if (glm::distance(p, q) < kSharedCornerTolerance) shared.push_back(p);
    if (shared.size() < 2) return std::nullopt;
    return std::array<glm::dvec3, 2>{shared[0], shared[1]};
}

int chooseRoot(const std::vector<Placed>& screens) {
    int floor = -1, best = 0, bestNeighbours = -1;
    for (int i = 0; i < static_cast<int>(screens.size()); ++i) {
        const Placed& s = screens[i];
        if (s.basis.normal.y > 0.99 && (floor < 0 || s.corners[0].y < screens[floor].corners[0].y)) floor = i;
        int neighbours = 0;
        for (const Placed& o : screens) neighbours += (&o != &s && sharedEdge(s, o)) ? 1 : 0;
        if (neighbours > bestNeighbours) {
            best = i;
            bestNeighbours = neighbours;
        }
    }
    return floor >= 0 ? floor : best;
}

// Hinges screen `s` about its edge shared with the already unfolded `from`, so that its normal
// becomes the root normal `n0`.
glm::dmat4 hinge(const Placed& from, const std::array<glm::dvec3, 2>& edge, const Placed& s, glm::dvec3 n0) {
    const glm::dvec3 a = glm::dvec3(from.unfold * glm::dvec4(edge[0], 1.0));
    const glm::dvec3 b = glm::dvec3(from.unfold * glm::dvec4(edge[1], 1.0));
    const glm::dvec3 axis = glm::normalize(b - a);
    const glm::dvec3 n = glm::dmat3(from.unfold) * s.basis.normal;
    const double angle = std::atan2(glm::dot(glm::cross(n, n0), axis), glm::dot(n, n0));
    return glm::translate(glm::dmat4(1.0), a) * glm::rotate(glm::dmat4(1.0), angle, axis) *
           glm::translate(glm::dmat4(1.0), -a) * from.unfold;
}

// Turns an unconnected screen flat about its own centre (identity when already parallel).
glm::dmat4 turnFlat(const Placed& s, glm::dvec3 n0) {
    const glm::dvec3 n = s.basis.normal;
    const double c = glm::dot(n, n0);
    if (c > 1.0 - 1e-12) return glm::dmat4(1.0);
    const glm::dvec3 cross = glm::cross(n, n0);
    const glm::dvec3 axis = glm::length(cross) > 1e-9 ? glm::normalize(cross) : s.basis.up;
    const glm::dvec3 centre = 0.5 * (s.corners[0] + s.corners[2]);
    return glm::translate(glm::dmat4(1.0), centre) *
           glm::rotate(glm::dmat4(1.0), std::acos(std::clamp(c, -1.0, 1.0)), axis) *
           glm::translate(glm::dmat4(1.0), -centre);
}

// Breadth-first over shared edges from the root; returns the unfolding order.
std::vector<int> unfoldAll(std::vector<Placed>& screens, int root) {
    const glm::dvec3 n0 = screens[root].basis.normal;
    std::vector<int> order{root};
    screens[root].placed = true;
    for (std::size_t head = 0; head < screens.size(); ++head) {
        if (head == order.size()) {  // nothing more connected: place the next loose screen
            int loose = 0;
            while (screens[loose].placed) ++loose;
            screens[loose].unfold = turnFlat(screens[loose], n0);
            screens[loose].placed = true;
            order.push_back(loose);
        }
        const Placed& from = screens[order[head]];
        for (int j = 0; j < static_cast<int>(screens.size()); ++j) {
            if (screens[j].placed) continue;
            if (auto edge = sharedEdge(from, screens[j])) {
                screens[j].unfold = hinge(from, *edge, screens[j], n0);
                screens[j].placed = true;
                order.push_back(j);
            }
        }
    }
    return order;
}

// Coordinates in the root screen's plane: metres along its right and up from its lower-left.
struct RootPlane {
    ScreenBasis basis;
    glm::dvec3 origin;

    // Where point `p` of screen `s` lands once unfolded.
    glm::dvec2 of(const Placed& s, glm::dvec3 p) const {
        const glm::dvec3 q = glm::dvec3(s.unfold * glm::dvec4(p, 1.0)) - origin;
        return {glm::dot(q, basis.right), glm::dot(q, basis.up)};
    }
    // Affine map from the unfolded screen's image pixels (x right, y down) to the plane.
    glm::dmat3 fromImage(const Placed& s, glm::ivec2 resolution) const {
        const glm::dvec2 topLeft = of(s, s.corners[3]);
        const glm::dvec2 alongX = of(s, s.corners[3] + s.basis.right * (s.basis.width / resolution.x)) - topLeft;
        const glm::dvec2 alongY = of(s, s.corners[3] - s.basis.up * (s.basis.height / resolution.y)) - topLeft;
        return glm::dmat3(glm::dvec3(alongX, 0), glm::dvec3(alongY, 0), glm::dvec3(topLeft, 1));
    }
};

}  // namespace

std::optional<FoldoutSample> FoldoutLayout::sample(glm::ivec2 canvas) const {
    const glm::dvec3 c(canvas.x + 0.5, canvas.y + 0.5, 1.0);
    for (const FoldoutTile& t : tiles) {
        const glm::dvec3 p = t.imageFromCanvas * c;
        const glm::ivec2 pixel(static_cast<int>(std::floor(p.x)), static_cast<int>(std::floor(p.y)));
        if (pixel.x >= 0 && pixel.y >= 0 && pixel.x < t.resolution.x && pixel.y < t.resolution.y)
            return FoldoutSample{t.screen, pixel};
    }
    return std::nullopt;
}

FoldoutLayout foldoutLayout(const std::vector<config::Screen>& screens, double pixelsPerMetre) {
    FoldoutLayout layout;
    if (screens.empty()) return layout;
    std::vector<Placed> placed;
    double finest = 0.0;
    for (const config::Screen& s : screens) {
        placed.push_back({screenBasis({s.lowerLeft, s.lowerRight, s.upperLeft}), cornersOf(s)});
        finest =
            std::max({finest, s.resolution.x / placed.back().basis.width, s.resolution.y / placed.back().basis.height});
    }
    const int root = chooseRoot(placed);
    const std::vector<int> order = unfoldAll(placed, root);
    const RootPlane plane{placed[root].basis, placed[root].corners[0]};
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const Placed& s : placed)
        for (const glm::dvec3& p : s.corners) {
            lo = glm::min(lo, plane.of(s, p));
            hi = glm::max(hi, plane.of(s, p));
        }

    // Sizes land on whole pixels up to rounding; the tolerance keeps 384.0000001 at 384.
    const glm::dvec2 extent = hi - lo;
    double k = pixelsPerMetre > 0.0 ? pixelsPerMetre : finest;
    k = std::min(k, config::kMaxResolution / std::max(extent.x, extent.y));
    layout.pixelsPerMetre = k;
    layout.size = glm::ivec2(std::ceil(extent.x * k - 1e-6), std::ceil(extent.y * k - 1e-6));
    // Canvas y runs down from the top of the unfolded screens.
    const glm::dmat3 canvasFromPlane(glm::dvec3(k, 0, 0), glm::dvec3(0, -k, 0), glm::dvec3(-lo.x * k, hi.y * k, 1));
    for (int i : order)
        layout.tiles.push_back({i, screens[i].resolution,
                                glm::inverse(canvasFromPlane * plane.fromImage(placed[i], screens[i].resolution))});
    return layout;
}

}  // namespace cavewall::display
