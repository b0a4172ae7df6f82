#include "walls/room_tour.h"

#include <algorithm>
#include <array>
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
// room's and doorway's and every other floor cell but a wall's, where the tour is held.
struct LegCells {
    int room = -1, door = -1;
    bool any = false;
};

// Legs over the grid (see the header), one Dijkstra search each.
class Router {
public:
    Router(const FloorGrid& grid, const FloorPlan& plan, const RoomTourOptions& options,
           const std::function<bool(glm::dvec2)>& holds = {})
        : g_(grid), plan_(plan), options_(options) {
        std::vector<std::uint8_t> blocked(plan.room.size());
        for (std::size_t c = 0; c < blocked.size(); ++c) blocked[c] = plan.room[c] < 0 && plan.opening[c] < 0;
        const std::vector<float> cells = chamferDistance(grid, blocked);
        clear_.resize(cells.size());
        // From a cell's centre to the nearest blocked cell's edge.
        for (std::size_t c = 0; c < cells.size(); ++c) clear_[c] = std::max(0.0, cells[c] - 0.5) * grid.cellSize;
        held_.assign(cells.size(), 1);
        if (holds)
            for (std::size_t c = 0; c < cells.size(); ++c) held_[c] = holds(grid.centre(static_cast<int>(c))) ? 1 : 0;
        cost_.assign(cells.size(), kInfinity);
        from_.assign(cells.size(), -1);
    }

    bool allowed(int c, LegCells leg) const {
        if (leg.any) return held_[c] && (plan_.room[c] >= 0 || plan_.opening[c] >= 0 || (g_.floor[c] && !g_.wall[c]));
        return plan_.room[c] == leg.room || (leg.door >= 0 && plan_.opening[c] == leg.door);
    }

    // The centre of the `any` cell nearest p within `reach` metres; nullopt when none.
    std::optional<glm::dvec2> nearestAllowed(glm::dvec2 p, double reach) const {
        const int c = g_.cellAt(p);
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
        const int start = g_.cellAt(a), goal = g_.cellAt(b);
        if (start < 0 || goal < 0) return {};
        if (start == goal) return {a, b};
        const std::vector<int> walk = shortest(
            start, [goal](int c) { return c == goal; }, cells);
        if (walk.size() < 2) return {};
        return thinned(walk, a, b, cells);
    }

    // The walk from a over `any` cells to the nearest cell of a room `wanted` marks: its
    // points (a, the turns, that cell's centre) and the room; {} and -1 when none is reached.
    std::pair<std::vector<glm::dvec2>, int> toNearestRoom(glm::dvec2 a, const std::vector<bool>& wanted) {
        const int start = g_.cellAt(a);
        if (start < 0) return {{}, -1};
        auto isGoal = [&](int c) { return plan_.room[c] >= 0 && wanted[plan_.room[c]]; };
        const std::vector<int> walk = shortest(start, isGoal, {-1, -1, true});
        if (walk.size() < 2 || !isGoal(walk.back())) return {{}, -1};
        return {thinned(walk, a, g_.centre(walk.back()), {-1, -1, true}), plan_.room[walk.back()]};
    }

private:
    double weight(int c) const {
        const double near = std::max(0.0, 1.0 - clear_[c] / options_.clearance);
        return 1.0 + (options_.nearWallCost - 1.0) * near;
    }

    // Dijkstra from `start` to the first cell `isGoal` takes, over the leg's cells: the cells
    // of the walk, in order (empty when it reaches none).
    template <class Goal>
    std::vector<int> shortest(int start, Goal isGoal, LegCells cells) {
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
        std::vector<int> touched{start};
        cost_[start] = 0.0;
        open.push({0.0, start});
        int goal = -1;
        while (!open.empty()) {
            const auto [cost, c] = open.top();
            open.pop();
            if (cost > cost_[c]) continue;
            if (isGoal(c)) {
                goal = c;
                break;
            }
            relax(c, cost, cells, open, touched);
        }
        std::vector<int> walk;
        for (int c = goal; c >= 0; c = c == start ? -1 : from_[c]) walk.push_back(c);
        std::reverse(walk.begin(), walk.end());
        for (int c : touched) {
            cost_[c] = kInfinity;
            from_[c] = -1;
        }
        return walk;
    }

    // One step of the search: the leg's 8-neighbours of cell c reached at `cost`.
    template <class Queue>
    void relax(int c, double cost, LegCells cells, Queue& open, std::vector<int>& touched) {
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

    // True when every cell the line p -> q passes (sampled every eighth of a cell) is the
    // leg's and at least `minClear` from the walls.
    bool straight(glm::dvec2 p, glm::dvec2 q, double minClear, LegCells cells) const {
        const int samples = 1 + static_cast<int>(std::ceil(8.0 * glm::length(q - p) / g_.cellSize));
        for (int t = 0; t <= samples; ++t) {
            const int c = g_.cellAt(glm::mix(p, q, double(t) / samples));
            if (c < 0 || !allowed(c, cells) || clear_[c] < minClear) return false;
        }
        return true;
    }

    // The walk's points thinned to its turns (the header's rule), from a to b.
    std::vector<glm::dvec2> thinned(const std::vector<int>& walk, glm::dvec2 a, glm::dvec2 b, LegCells cells) const {
        const std::size_t last = walk.size() - 1;
        auto point = [&](std::size_t n) { return n == 0 ? a : n == last ? b : g_.centre(walk[n]); };
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
    std::vector<double> clear_;       // per cell, metres to the nearest cell no leg may use
    std::vector<std::uint8_t> held_;  // per cell, whether `holds` takes its centre
    std::vector<double> cost_;        // per cell, the search's cost so far (infinite between searches)
    std::vector<int> from_;           // per cell, the search's previous cell
};

// Where the walk passes each doorway (its centre when that lies in one of its cells, else the
// centre of its cell nearest the centre) and room `room`'s cell nearest `near`: one scan.
struct Anchors {
    std::vector<glm::dvec2> doors;
    glm::dvec2 roomCell{0.0};
};

Anchors anchorsOf(const FloorGrid& g, const FloorPlan& plan, int room, glm::dvec2 near) {
    Anchors out;
    std::vector<double> best(plan.doorways.size(), kInfinity);
    for (const Doorway& d : plan.doorways) out.doors.push_back(d.position);
    for (std::size_t d = 0; d < plan.doorways.size(); ++d) {
        const int c = g.cellAt(plan.doorways[d].position);
        if (c >= 0 && plan.opening[c] == static_cast<int>(d)) best[d] = 0.0;
    }
    out.roomCell = plan.rooms[room].inner;
    double roomBest = kInfinity;
    for (int c = 0; c < g.nx * g.nz; ++c) {
        const glm::dvec2 centre = g.centre(c);
        if (plan.room[c] == room && glm::length(centre - near) < roomBest) {
            roomBest = glm::length(centre - near);
            out.roomCell = centre;
        }
        const int d = plan.opening[c];
        if (d < 0 || d >= static_cast<int>(out.doors.size())) continue;
        const double distance = glm::length(centre - plan.doorways[d].position);
        if (distance < best[d]) {
            best[d] = distance;
            out.doors[d] = centre;
        }
    }
    return out;
}

double lengthOf(const std::vector<glm::dvec2>& points) {
    double metres = 0.0;
    for (std::size_t n = 1; n < points.size(); ++n) metres += glm::length(points[n] - points[n - 1]);
    return metres;
}

// The walk through one doorway's legs: from rooms[s]'s inner point to the doorway, per side s.
struct DoorLegs {
    std::array<std::vector<glm::dvec2>, 2> toDoor;
    double metres = kInfinity;  // both legs; infinite when the doorway is not walked
};

// The tour under construction (see the header): where it stands and what it has seen.
class Tour {
public:
    Tour(const FloorGrid& g, const FloorPlan& plan, double eyeY, const RoomTourOptions& options,
         const std::function<bool(glm::dvec2)>& holds)
        : plan_(plan), eyeY_(eyeY), holds_(holds), router_(g, plan, options, holds), seen_(plan.rooms.size(), false),
          skipped_(plan.rooms.size(), false) {
        for (std::size_t r = 1; r < plan.rooms.size(); ++r)
            if (plan.rooms[r].area > plan.rooms[largest_].area) largest_ = static_cast<int>(r);
        const Room& room = plan.rooms[largest_];
        anchors_ = anchorsOf(g, plan, largest_, 0.5 * (room.lo + room.hi));
        for (std::size_t d = 0; d < plan.doorways.size(); ++d) legs_.push_back(doorLegs(static_cast<int>(d)));
    }

    std::vector<glm::dvec3> walk() {
        at_ = largest_;
        seen_[at_] = true;
        add({plan_.rooms[at_].inner});
        while (throughDoorways() || overFloor()) {}
        if (path_.size() < 2) add(router_.leg(plan_.rooms[largest_].inner, anchors_.roomCell, {largest_, -1}));
        return path_;
    }

private:
    bool held(const std::vector<glm::dvec2>& points) const {
        return !holds_ || std::all_of(points.begin(), points.end(), holds_);
    }

    DoorLegs doorLegs(int d) {
        const Doorway& door = plan_.doorways[d];
        DoorLegs out;
        for (int s = 0; s < 2; ++s)
            out.toDoor[s] = router_.leg(plan_.rooms[door.rooms[s]].inner, anchors_.doors[d], {door.rooms[s], d});
        if (!out.toDoor[0].empty() && !out.toDoor[1].empty() && held(out.toDoor[0]) && held(out.toDoor[1]))
            out.metres = lengthOf(out.toDoor[0]) + lengthOf(out.toDoor[1]);
        return out;
    }

    void add(const std::vector<glm::dvec2>& points) {
        for (const glm::dvec2& p : points) {
            const glm::dvec3 q(p.x, eyeY_, p.y);
            if (path_.empty() || path_.back() != q) path_.push_back(q);
        }
    }

    // Walks the shortest way over walked doorways to the nearest room not seen; false when
    // the doorways lead to none.
    bool throughDoorways() {
        const std::size_t rooms = plan_.rooms.size();
        std::vector<double> metres(rooms, kInfinity);
        std::vector<int> via(rooms, -1);
        using Entry = std::pair<double, int>;
        std::priority_queue<Entry, std::vector<Entry>, std::greater<>> open;
        metres[at_] = 0.0;
        open.push({0.0, at_});
        int target = -1;
        while (!open.empty() && target < 0) {
            const auto [m, r] = open.top();
            open.pop();
            if (m > metres[r]) continue;
            if (!seen_[r]) target = r;
            for (std::size_t d = 0; d < legs_.size() && target < 0; ++d) {
                const Doorway& door = plan_.doorways[d];
                if ((door.rooms[0] != r && door.rooms[1] != r) || legs_[d].metres == kInfinity) continue;
                const int next = door.rooms[0] == r ? door.rooms[1] : door.rooms[0];
                if (m + legs_[d].metres >= metres[next]) continue;
                metres[next] = m + legs_[d].metres;
                via[next] = static_cast<int>(d);
                open.push({metres[next], next});
            }
        }
        if (target < 0) return false;
        std::vector<int> doors;
        for (int r = target; r != at_;) {
            const Doorway& door = plan_.doorways[via[r]];
            doors.push_back(via[r]);
            r = door.rooms[0] == r ? door.rooms[1] : door.rooms[0];
        }
        std::reverse(doors.begin(), doors.end());
        for (int d : doors) walkThrough(d);
        return true;
    }

    void walkThrough(int d) {
        const Doorway& door = plan_.doorways[d];
        const int from = door.rooms[0] == at_ ? 0 : 1;
        add(legs_[d].toDoor[from]);
        std::vector<glm::dvec2> in = legs_[d].toDoor[1 - from];
        std::reverse(in.begin(), in.end());
        add(in);
        at_ = door.rooms[1 - from];
        seen_[at_] = true;
    }

    // Walks over other floor (a closed opening, floor that is no room) to the nearest room not
    // seen, on to its inner point; false when none is reached.
    bool overFloor() {
        for (;;) {
            std::vector<bool> wanted(plan_.rooms.size());
            for (std::size_t r = 0; r < wanted.size(); ++r) wanted[r] = !seen_[r] && !skipped_[r];
            auto [route, room] = router_.toNearestRoom(plan_.rooms[at_].inner, wanted);
            if (room < 0) return false;
            const std::vector<glm::dvec2> in = router_.leg(route.back(), plan_.rooms[room].inner, {room, -1});
            if (in.empty() || !held(route) || !held(in)) {
                skipped_[room] = true;
                continue;
            }
            add(route);
            add(in);
            at_ = room;
            seen_[at_] = true;
            return true;
        }
    }

    const FloorPlan& plan_;
    double eyeY_;
    const std::function<bool(glm::dvec2)>& holds_;
    Router router_;
    Anchors anchors_;
    std::vector<DoorLegs> legs_;
    std::vector<bool> seen_, skipped_;
    int largest_ = 0, at_ = 0;
    std::vector<glm::dvec3> path_;
};

}  // namespace

std::vector<glm::dvec3> roomTour(const FloorGrid& g, const FloorPlan& plan, double eyeY, const RoomTourOptions& options,
                                 const std::function<bool(glm::dvec2)>& holds) {
    assert(!plan.rooms.empty() && options.clearance > 0.0 && options.nearWallCost >= 1.0);
    return Tour(g, plan, eyeY, options, holds).walk();
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
