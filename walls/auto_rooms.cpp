#include "walls/auto_rooms.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace cavewall::walls {

namespace {

double overlap1d(double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// Gaps of at least `minGap` in [from, to] not covered by `spans`.
std::vector<std::pair<double, double>> gapsIn(double from, double to, std::vector<std::pair<double, double>> spans,
                                              double minGap) {
    std::sort(spans.begin(), spans.end());
    std::vector<std::pair<double, double>> gaps;
    double x = from;
    for (const auto& [a, b] : spans) {
        if (b <= x) continue;
        if (a >= to) break;
        if (a - x >= minGap) gaps.push_back({x, std::min(a, to)});
        x = std::max(x, b);
    }
    if (to - x >= minGap) gaps.push_back({x, to});
    return gaps;
}

}  // namespace

void makeRooms(scenes::SceneDescription& d, const std::vector<WallPiece>& pieces, double floorY, double ceilingY) {
    constexpr double kOnLine = 0.05, kMinDoor = 0.3, kFloorSlack = 0.1;
    std::vector<scenes::VirtualWall> walls;
    for (const scenes::VirtualWall& w : d.walls) {
        const int axis = std::abs(w.lowerLeft.x - w.lowerRight.x) < 1e-9 ? 0 : 2;  // the boundary's normal
        const int along = axis == 0 ? 2 : 0;
        const double at = w.lowerLeft[axis];
        const double from = std::min(w.lowerLeft[along], w.lowerRight[along]);
        const double to = std::max(w.lowerLeft[along], w.lowerRight[along]);
        std::vector<std::pair<double, double>> full;
        std::vector<const WallPiece*> onLine;
        for (const WallPiece& p : pieces) {
            if (p.axis != axis || std::abs(p.at - at) > kOnLine || overlap1d(p.from, p.to, from, to) <= 0.0) continue;
            onLine.push_back(&p);
            if (p.bottom <= floorY + kFloorSlack) full.push_back({p.from, p.to});
        }
        if (onLine.empty()) {
            walls.push_back(w);  // open floor: a virtual wall
            continue;
        }
        const glm::dvec3 frontSide = w.lowerLeft + glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft);
        const glm::dvec2 front{frontSide.x, frontSide.z};
        int door = 0;
        for (const auto& [a, b] : gapsIn(from, to, full, kMinDoor)) {
            double top = ceilingY;
            for (const WallPiece* p : onLine)
                if (p->bottom > floorY + kFloorSlack && overlap1d(p->from, p->to, a, b) > 0.0)
                    top = std::min(top, p->bottom);
            const glm::dvec2 pa = axis == 0 ? glm::dvec2(at, a) : glm::dvec2(a, at);
            const glm::dvec2 pb = axis == 0 ? glm::dvec2(at, b) : glm::dvec2(b, at);
            scenes::VirtualWall portal = wallBetween(pa, pb, floorY, top, front);
            portal.name = "door " + w.name + (door > 0 ? " " + std::to_string(door + 1) : "");
            portal.cells = w.cells;
            portal.kind = scenes::WallKind::Portal;
            walls.push_back(portal);
            ++door;
        }
    }
    d.walls = std::move(walls);
    for (const WallPiece& p : pieces) {
        scenes::RealWall r;
        r.name = "real " + std::to_string(d.realWalls.size());
        const int along = p.axis == 0 ? 2 : 0;
        r.lowerLeft[p.axis] = r.lowerRight[p.axis] = r.upperLeft[p.axis] = p.at;
        r.lowerLeft[along] = r.upperLeft[along] = p.from;
        r.lowerRight[along] = p.to;
        r.lowerLeft.y = r.lowerRight.y = p.bottom;
        r.upperLeft.y = p.top;
        d.realWalls.push_back(r);
    }
}

// Positions along `axis` of lines of wall pieces strictly inside (lo, hi) whose pieces reaching
// the floor cover at least half of `extent`: where a building's rooms meet.
std::vector<double> wallLines(const std::vector<WallPiece>& pieces, int axis, double lo, double hi, double extent,
                              double floorY) {
    std::vector<double> lines;
    std::vector<const WallPiece*> sorted;
    for (const WallPiece& p : pieces)
        if (p.axis == axis && p.at > lo + 0.25 && p.at < hi - 0.25) sorted.push_back(&p);
    std::sort(sorted.begin(), sorted.end(), [](const WallPiece* a, const WallPiece* b) { return a->at < b->at; });
    for (std::size_t i = 0; i < sorted.size();) {
        std::size_t j = i;
        double covered = 0.0, sum = 0.0;
        while (j < sorted.size() && sorted[j]->at - sorted[i]->at <= 0.05) {
            if (sorted[j]->bottom <= floorY + 0.1) covered += sorted[j]->to - sorted[j]->from;
            sum += sorted[j]->at;
            ++j;
        }
        if (covered >= 0.5 * extent) lines.push_back(sum / static_cast<double>(j - i));
        i = j;
    }
    return lines;
}

}  // namespace cavewall::walls
