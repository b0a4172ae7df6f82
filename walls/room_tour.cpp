#include "walls/room_tour.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <queue>
#include <utility>

namespace cavewall::walls {

namespace {

constexpr int kSteps[8][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}, {1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The cells one leg may use: those of `room` and of doorway `door` (-1: none); with `any`, every
// room's and doorway's and every other floor cell but a wall's.
struct LegCells {
    int room = -1, door = -1;
    bool any = false;
};

// Legs over the grid (see the header), one Dijkstra search each.
class Router {
public:
    Router(const FloorGrid& grid, const FloorPlan& plan, const RoomTourOptions& options)
        : g_(grid), plan_(plan), options_(options) {
        std::vector<std::uint8_t> blocked(plan.room.size());
        for (std::size_t c = 0; c < blocked.size(); ++c) blocked[c] = plan.room[c] < 0 && plan.opening[c] < 0;
        const std::vector<float> cells = chamferDistance(grid, blocked);
        clear_.resize(cells.size());
        // From a cell's centre to the nearest blocked cell's edge.
        for (std::size_t c = 0; c < cells.size(); ++c) clear_[c] = std::max(0.0, cells[c] - 0.5) * grid.cellSize;
        cost_.assign(cells.size(), kInfinity);
        from_.assign(cells.size(), -1);
    }

    // The cell holding p, -1 off the grid.
    int cellAt(glm::dvec2 p) const {
        const glm::dvec2 q = (p - g_.origin) / g_.cellSize;
        const int i = static_cast<int>(std::floor(q.x)), k = static_cast<int>(std::floor(q.y));
        return g_.inside(i, k) ? g_.index(i, k) : -1;
    }

    bool allowed(int c, LegCells leg) const {
        if (leg.any) return plan_.room[c] >= 0 || plan_.opening[c] >= 0 || (g_.floor[c] && !g_.wall[c]);
        return plan_.room[c] == leg.room || (leg.door >= 0 && plan_.opening[c] == leg.door);
    }

    // The centre of the `any` cell nearest p within `reach` metres; nullopt when none.
    std::optional<glm::dvec2> nearestAllowed(glm::dvec2 p, double reach) const {
        const int c = cellAt(p);
        if (c >= 0 && allowed(c, {-1, -1, true})) return p;
        const glm::dvec2 q = (p - g_.origin) / g_.cellSize;
        const int r = static_cast<int>(std::ceil(reach / g_.cellSize));
        std::optional<glm::dvec2> best;
        double distance = reach;
        for (int k = static_cast<int>(q.y) - r; k <= static_cast<int>(q.y) + r; ++k)
            for (int i = static_cast<int>(q.x) - r; i <= static_cast<int>(q.x) + r; ++i)
                if (g_.inside(i, k) && allowed(g_.index(i, k), {-1, -1, true}) &&
                    glm::length(g_.centre(i, k) - p) <= distance) {
                    distance = glm::length(g_.centre(i, k) - p);
                    best = g_.centre(i, k);
                }
        return best;
    }

    // The walk from a to b (both in the leg's cells) as points: a, its turns, b; empty when
    // the search finds none.
    std::vector<glm::dvec2> leg(glm::dvec2 a, glm::dvec2 b, LegCells cells) {
        const int start = cellAt(a), goal = cellAt(b);
        if (start < 0 || goal < 0) return {};
        if (start == goal) return {a, b};
        const std::vector<int> walk = shortest(start, goal, cells);
        if (walk.size() < 2) return {};
        return thinned(walk, a, b, cells);
    }

private:
    glm::dvec2 centre(int c) const { return g_.centre(c % g_.nx, c / g_.nx); }

    double weight(int c) const {
        const double near = std::max(0.0, 1.0 - clear_[c] / options_.clearance);
        return 1.0 + (options_.nearWallCost - 1.0) * near;
    }

    // Dijkstra from `start` to `goal` over the leg's cells: the cells of the walk, in order.
    std::vector<int> shortest(int start, int goal, LegCells cells) {
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
        std::vector<int> touched{start};
        cost_[start] = 0.0;
        open.push({0.0, start});
        while (!open.empty()) {
            const auto [cost, c] = open.top();
            open.pop();
            if (c == goal) break;
            if (cost > cost_[c]) continue;
            const int i = c % g_.nx, k = c / g_.nx;
            for (const auto& s : kSteps) {
                if (!g_.inside(i + s[0], k + s[1])) continue;
                const int n = g_.index(i + s[0], k + s[1]);
                if (!allowed(n, cells)) continue;
                const bool diagonal = s[0] != 0 && s[1] != 0;
                if (diagonal && (!allowed(g_.index(i + s[0], k), cells) || !allowed(g_.index(i, k + s[1]), cells)))
                    continue;
                const double length = g_.cellSize * (diagonal ? M_SQRT2 : 1.0);
                const double next = cost + length * 0.5 * (weight(c) + weight(n));
                if (next >= cost_[n]) continue;
                if (cost_[n] == kInfinity) touched.push_back(n);
                cost_[n] = next;
                from_[n] = c;
                open.push({next, n});
            }
        }
        std::vector<int> walk;
        if (cost_[goal] < kInfinity)
            for (int c = goal; c >= 0; c = c == start ? -1 : from_[c]) walk.push_back(c);
        std::reverse(walk.begin(), walk.end());
        for (int c : touched) {
            cost_[c] = kInfinity;
            from_[c] = -1;
        }
        return walk;
    }

    // True when every cell the line p -> q passes (sampled every eighth of a cell) is the
    // leg's and at least `minClear` from the walls.
    bool straight(glm::dvec2 p, glm::dvec2 q, double minClear, LegCells cells) const {
        const int samples = 1 + static_cast<int>(std::ceil(8.0 * glm::length(q - p) / g_.cellSize));
        for (int t = 0; t <= samples; ++t) {
            const int c = cellAt(glm::mix(p, q, double(t) / samples));
            if (c < 0 || !allowed(c, cells) || clear_[c] < minClear) return false;
        }
        return true;
    }

    // The walk's points thinned to its turns (the header's rule), from a to b.
    std::vector<glm::dvec2> thinned(const std::vector<int>& walk, glm::dvec2 a, glm::dvec2 b, LegCells cells) const {
        const std::size_t last = walk.size() - 1;
        auto point = [&](std::size_t n) { return n == 0 ? a : n == last ? b : centre(walk[n]); };
        std::vector<glm::dvec2> out{a};
        std::size_t anchor = 0;
        while (anchor < last) {
            double runClear = std::min(clear_[walk[anchor]], clear_[walk[anchor + 1]]);
            std::size_t reach = anchor + 1;
            for (std::size_t next = anchor + 2; next <= last; ++next) {
                const double run = std::min(runClear, clear_[walk[next]]);
                const double minClear = std::min(run, options_.clearance) - 0.5 * g_.cellSize;
                if (!straight(point(anchor), point(next), minClear, cells)) break;
                runClear = run;
                reach = next;
            }
            out.push_back(point(reach));
            anchor = reach;
        }
        return out;
    }

    const FloorGrid& g_;
    const FloorPlan& plan_;
    const RoomTourOptions& options_;
    std::vector<double> clear_;  // per cell, metres to the nearest cell no leg may use
    std::vector<double> cost_;   // per cell, the search's cost so far (infinite between searches)
    std::vector<int> from_;      // per cell, the search's previous cell
};

// Where the walk passes doorway d: its centre when that lies in one of its cells, else the
// centre of its cell nearest the centre.
std::vector<glm::dvec2> doorPoints(const FloorGrid& g, const FloorPlan& plan, const Router& router) {
    std::vector<glm::dvec2> points;
    std::vector<double> best(plan.doorways.size(), kInfinity);
    for (const Doorway& d : plan.doorways) points.push_back(d.position);
    for (std::size_t d = 0; d < plan.doorways.size(); ++d) {
        const int c = router.cellAt(plan.doorways[d].position);
        if (c >= 0 && plan.opening[c] == static_cast<int>(d)) best[d] = 0.0;
    }
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i) {
            const int d = plan.opening[g.index(i, k)];
            if (d < 0 || d >= static_cast<int>(points.size())) continue;
            const double distance = glm::length(g.centre(i, k) - plan.doorways[d].position);
            if (distance < best[d]) {
                best[d] = distance;
                points[d] = g.centre(i, k);
            }
        }
    return points;
}

// The centre of room r's cell nearest p.
glm::dvec2 roomCellNear(const FloorGrid& g, const FloorPlan& plan, int r, glm::dvec2 p) {
    glm::dvec2 best = plan.rooms[r].inner;
    double distance = kInfinity;
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i)
            if (plan.room[g.index(i, k)] == r && glm::length(g.centre(i, k) - p) < distance) {
                distance = glm::length(g.centre(i, k) - p);
                best = g.centre(i, k);
            }
    return best;
}

}  // namespace

std::vector<glm::dvec3> roomTour(const FloorGrid& g, const FloorPlan& plan, double eyeY, const RoomTourOptions& options,
                                 const std::function<bool(glm::dvec2)>& holds) {
    assert(!plan.rooms.empty() && options.clearance > 0.0 && options.nearWallCost >= 1.0);
    Router router(g, plan, options);
    const std::vector<glm::dvec2> doors = doorPoints(g, plan, router);
    std::vector<glm::dvec3> path;
    auto add = [&](const std::vector<glm::dvec2>& points) {
        for (const glm::dvec2& p : points) {
            const glm::dvec3 q(p.x, eyeY, p.y);
            if (path.empty() || path.back() != q) path.push_back(q);
        }
    };
    std::vector<bool> seen(plan.rooms.size(), false);
    // Depth first; the walk stands at room r's inner point.
    std::function<void(int)> visit = [&](int r) {
        seen[r] = true;
        for (std::size_t d = 0; d < plan.doorways.size(); ++d) {
            const Doorway& door = plan.doorways[d];
            if (door.rooms[0] != r && door.rooms[1] != r) continue;
            const int next = door.rooms[0] == r ? door.rooms[1] : door.rooms[0];
            if (seen[next]) continue;
            const int through = static_cast<int>(d);
            std::vector<glm::dvec2> out = router.leg(plan.rooms[r].inner, doors[d], {r, through});
            std::vector<glm::dvec2> in = router.leg(doors[d], plan.rooms[next].inner, {next, through});
            if (out.empty() || in.empty()) continue;  // the doorway's cells do not join the rooms'
            if (holds && !(std::all_of(out.begin(), out.end(), holds) && std::all_of(in.begin(), in.end(), holds)))
                continue;
            add(out);
            add(in);
            visit(next);
            std::reverse(in.begin(), in.end());
            std::reverse(out.begin(), out.end());
            add(in);
            add(out);
        }
    };
    int largest = 0;
    for (std::size_t r = 1; r < plan.rooms.size(); ++r)
        if (plan.rooms[r].area > plan.rooms[largest].area) largest = static_cast<int>(r);
    add({plan.rooms[largest].inner});
    visit(largest);
    if (path.size() < 2) {
        const Room& room = plan.rooms[largest];
        const glm::dvec2 middle = roomCellNear(g, plan, largest, 0.5 * (room.lo + room.hi));
        add(router.leg(room.inner, middle, {largest, -1}));
    }
    return path;
}

std::vector<glm::dvec2> roomRoute(const FloorGrid& g, const FloorPlan& plan, glm::dvec2 from, glm::dvec2 to,
                                  const RoomTourOptions& options) {
    assert(options.clearance > 0.0 && options.nearWallCost >= 1.0);
    constexpr double kReach = 1.0;  // metres from a point to its room or doorway cell
    Router router(g, plan, options);
    const std::optional<glm::dvec2> start = router.nearestAllowed(from, kReach);
    const std::optional<glm::dvec2> goal = router.nearestAllowed(to, kReach);
    if (!start || !goal) return {};
    const std::vector<glm::dvec2> walk = router.leg(*start, *goal, {-1, -1, true});
    if (walk.empty()) return {};
    std::vector<glm::dvec2> out{from};
    for (const glm::dvec2& p : walk)
        if (p != out.back()) out.push_back(p);
    if (to != out.back()) out.push_back(to);
    return out;
}

}  // namespace cavewall::walls
