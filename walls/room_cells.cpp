#include "walls/room_cells.h"

#include "walls/auto_rooms.h"
#include "walls/room_tour.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace cavewall::walls {

namespace {

// A rectangle of grid cells, [i0, i1) x [k0, k1).
struct Box {
    int i0 = 0, k0 = 0, i1 = 0, k1 = 0;
};

// Prefix sums over the grid: room cells, and cuts' blocked cells along each grid line.
struct Sums {
    const FloorGrid& g;
    std::vector<int> rooms;     // (nz + 1) x (nx + 1): room cells in [0, i) x [0, k)
    std::vector<int> blockedX;  // (nx + 1) x (nz + 1): line x = i, rows [0, k) not room on both sides
    std::vector<int> blockedZ;  // (nz + 1) x (nx + 1): line z = k, columns [0, i)

    explicit Sums(const FloorGrid& grid, const FloorPlan& plan) : g(grid) {
        const int nx = g.nx, nz = g.nz;
        auto isRoom = [&](int i, int k) { return g.inside(i, k) && plan.room[g.index(i, k)] >= 0; };
        rooms.assign(static_cast<std::size_t>(nz + 1) * (nx + 1), 0);
        for (int k = 0; k < nz; ++k)
            for (int i = 0; i < nx; ++i)
                rooms[(k + 1) * (nx + 1) + i + 1] = rooms[k * (nx + 1) + i + 1] + rooms[(k + 1) * (nx + 1) + i] -
                                                    rooms[k * (nx + 1) + i] + (isRoom(i, k) ? 1 : 0);
        blockedX.assign(static_cast<std::size_t>(nx + 1) * (nz + 1), 0);
        for (int i = 0; i <= nx; ++i)
            for (int k = 0; k < nz; ++k)
                blockedX[i * (nz + 1) + k + 1] = blockedX[i * (nz + 1) + k] + !(isRoom(i - 1, k) && isRoom(i, k));
        blockedZ.assign(static_cast<std::size_t>(nz + 1) * (nx + 1), 0);
        for (int k = 0; k <= nz; ++k)
            for (int i = 0; i < nx; ++i)
                blockedZ[k * (nx + 1) + i + 1] = blockedZ[k * (nx + 1) + i] + !(isRoom(i, k - 1) && isRoom(i, k));
    }
    int roomCells(const Box& b) const {
        const int w = g.nx + 1;
        return rooms[b.k1 * w + b.i1] - rooms[b.k0 * w + b.i1] - rooms[b.k1 * w + b.i0] + rooms[b.k0 * w + b.i0];
    }
};

// The best cut of `b` (see the header), when one crosses little enough open floor.
std::optional<std::pair<Box, Box>> bestCut(const Sums& s, const Box& b, int minSide, const RoomCellOptions& options) {
    double bestScore = std::numeric_limits<double>::infinity();
    std::optional<std::pair<Box, Box>> best;
    const double cell = s.g.cellSize;
    // `open`: cells of the cut with room cells on both sides; `offMiddle`: in half cells.
    auto consider = [&](int open, int length, int offMiddle, const Box& first, const Box& second) {
        const double limit = std::max(options.maxOpenCut, options.maxOpenShare * length * cell);
        if (open * cell > limit + 1e-9 || s.roomCells(first) < minSide || s.roomCells(second) < minSide) return;
        const double score = open * cell + options.offMiddleWeight * 0.5 * offMiddle * cell;
        if (score < bestScore) {
            bestScore = score;
            best = std::pair{first, second};
        }
    };
    const int h = s.g.nz + 1, w = s.g.nx + 1;
    for (int i = b.i0 + 1; i < b.i1; ++i) {
        const int blocked = s.blockedX[i * h + b.k1] - s.blockedX[i * h + b.k0];
        consider(b.k1 - b.k0 - blocked, b.k1 - b.k0, std::abs(2 * i - b.i0 - b.i1), {b.i0, b.k0, i, b.k1},
                 {i, b.k0, b.i1, b.k1});
    }
    for (int k = b.k0 + 1; k < b.k1; ++k) {
        const int blocked = s.blockedZ[k * w + b.i1] - s.blockedZ[k * w + b.i0];
        consider(b.i1 - b.i0 - blocked, b.i1 - b.i0, std::abs(2 * k - b.k0 - b.k1), {b.i0, b.k0, b.i1, k},
                 {b.i0, k, b.i1, b.k1});
    }
    return best;
}

// True when one room holds at least `share` of the box's room cells.
bool oneRoom(const FloorGrid& g, const FloorPlan& plan, const Box& b, double share) {
    std::map<int, int> count;
    int all = 0;
    for (int k = b.k0; k < b.k1; ++k)
        for (int i = b.i0; i < b.i1; ++i)
            if (const int r = plan.room[g.index(i, k)]; r >= 0) {
                ++count[r];
                ++all;
            }
    int most = 0;
    for (const auto& [r, n] : count) most = std::max(most, n);
    return all == 0 || most >= share * all;
}

// The rooms' bounds in cells.
Box roomBounds(const FloorGrid& g, const FloorPlan& plan) {
    Box b{g.nx, g.nz, 0, 0};
    for (int k = 0; k < g.nz; ++k)
        for (int i = 0; i < g.nx; ++i)
            if (plan.room[g.index(i, k)] >= 0) {
                b = {std::min(b.i0, i), std::min(b.k0, k), std::max(b.i1, i + 1), std::max(b.k1, k + 1)};
            }
    return b;
}

std::vector<Box> partition(const FloorGrid& g, const FloorPlan& plan, const RoomCellOptions& options) {
    const Sums sums(g, plan);
    const int minSide = static_cast<int>(std::ceil(options.minRoomArea / (g.cellSize * g.cellSize) - 1e-9));
    std::vector<Box> leaves{roomBounds(g, plan)};
    std::vector<bool> final{false};
    while (static_cast<int>(leaves.size()) < options.maxCells) {
        int pick = -1;
        for (std::size_t n = 0; n < leaves.size(); ++n)
            if (!final[n] && (pick < 0 || sums.roomCells(leaves[n]) > sums.roomCells(leaves[pick])))
                pick = static_cast<int>(n);
        if (pick < 0) break;
        const auto cut = oneRoom(g, plan, leaves[pick], options.dominantShare)
                             ? std::nullopt
                             : bestCut(sums, leaves[pick], minSide, options);
        if (!cut) {
            final[pick] = true;
            continue;
        }
        leaves[pick] = cut->first;
        leaves.push_back(cut->second);
        final.push_back(false);
    }
    return leaves;
}

// What a shared edge is at one step: a doorway's portal (its index), open floor, a wall, or
// nothing (no floor or floor that is no room on a side: a void, a gallery's edge), left bare.
constexpr int kOpen = -1, kWall = -2, kNothing = -3;

int edgeClass(const FloorPlan& plan, int c0, int c1) {
    if (plan.opening[c0] >= 0) return plan.opening[c0];
    if (plan.opening[c1] >= 0) return plan.opening[c1];
    if (plan.room[c0] >= 0 && plan.room[c1] >= 0) return kOpen;
    if (plan.barrier[c0] || plan.barrier[c1]) return kWall;
    return kNothing;
}

struct Builder {
    const FloorGrid& g;
    const FloorPlan& plan;
    const RoomCellOptions& options;
    double floorY, ceilingY;
    scenes::SceneDescription& d;
    int doors = 0;

    glm::dvec2 at(int i, int k) const { return g.origin + g.cellSize * glm::dvec2(i, k); }
    glm::dvec2 centre(int cell) const {
        const auto& r = d.cells[cell].region;
        return 0.25 * (r[0] + r[1] + r[2] + r[3]);
    }

    // One run of the edge between cells a and b from p to q (x, z).
    void emit(int kind, int a, int b, glm::dvec2 p, glm::dvec2 q) {
        if (kind == kNothing) return;  // a wall's run counts at any length (see the header)
        if (kind == kWall) {
            auto r = wallBetween<scenes::RealWall>(p, q, floorY, ceilingY, centre(a));
            r.name = "real " + std::to_string(d.realWalls.size());
            d.realWalls.push_back(r);
            return;
        }
        const double top = kind == kOpen ? ceilingY : std::min(ceilingY, floorY + options.portalHeight);
        auto w = wallBetween(p, q, floorY, top, centre(a));
        w.cells = {a, b};
        w.kind = kind == kOpen ? scenes::WallKind::Virtual : scenes::WallKind::Portal;
        w.name = d.cells[a].name + "|" + d.cells[b].name;
        if (kind != kOpen) w.name = "door " + w.name + " " + std::to_string(++doors);
        d.walls.push_back(w);
    }

    // The edge along grid line `line` (x = line when `alongZ`, else z = line) over [from, to).
    void walkEdge(int a, int b, bool alongZ, int line, int from, int to) {
        int start = from, kind = kNothing;
        auto point = [&](int s) { return alongZ ? at(line, s) : at(s, line); };
        for (int s = from; s <= to; ++s) {
            int here = kNothing;
            if (s < to) {
                const int c0 = alongZ ? g.index(line - 1, s) : g.index(s, line - 1);
                const int c1 = alongZ ? g.index(line, s) : g.index(s, line);
                here = edgeClass(plan, c0, c1);
            }
            if (s > from && (s == to || here != kind)) {
                emit(kind, a, b, point(start), point(s));
                start = s;
            }
            kind = here;
        }
    }
};

}  // namespace

StoreyRooms findStoreyRooms(const scenes::Scene& scene, double floorY, double ceilingY, glm::dvec2 lo, glm::dvec2 hi,
                            const FloorGridOptions& gridOptions, const RoomOptions& roomOptions) {
    StoreyRooms out;
    out.grid = rasteriseStorey(scene, floorY, ceilingY, lo, hi, gridOptions);
    if (out.grid.wallElements > 0) {
        out.plan = findRooms(out.grid.grid, roomOptions);
        return out;
    }
    const std::size_t cells = out.grid.grid.wall.size();
    out.plan.room.assign(cells, -1);
    out.plan.opening.assign(cells, -1);
    out.plan.barrier = out.grid.grid.wall;
    return out;
}

scenes::SceneDescription describeRooms(const scenes::SceneDescription& base, const FloorGrid& g, const FloorPlan& plan,
                                       double floorY, double ceilingY, double eyeHeight,
                                       const RoomCellOptions& options) {
    assert(!plan.rooms.empty());
    scenes::SceneDescription d = base;
    d.cells.clear();
    d.walls.clear();
    d.realWalls.clear();
    d.walkPath.clear();
    d.wallPath.clear();
    const std::vector<Box> leaves = partition(g, plan, options);
    for (const Box& b : leaves) {
        scenes::Cell c;
        c.name = "R" + std::to_string(d.cells.size() + 1);
        c.floorY = floorY;
        const glm::dvec2 lo = g.origin + g.cellSize * glm::dvec2(b.i0, b.k0);
        const glm::dvec2 hi = g.origin + g.cellSize * glm::dvec2(b.i1, b.k1);
        c.region = {{lo.x, hi.y}, {hi.x, hi.y}, {hi.x, lo.y}, {lo.x, lo.y}};  // counter-clockwise from above
        d.cells.push_back(std::move(c));
    }
    Builder build{g, plan, options, floorY, ceilingY, d};
    for (std::size_t a = 0; a < leaves.size(); ++a)
        for (std::size_t b = 0; b < leaves.size(); ++b) {
            const Box& p = leaves[a];
            const Box& q = leaves[b];
            if (p.i1 == q.i0 && std::max(p.k0, q.k0) < std::min(p.k1, q.k1))
                build.walkEdge(int(a), int(b), true, p.i1, std::max(p.k0, q.k0), std::min(p.k1, q.k1));
            if (p.k1 == q.k0 && std::max(p.i0, q.i0) < std::min(p.i1, q.i1))
                build.walkEdge(int(a), int(b), false, p.k1, std::max(p.i0, q.i0), std::min(p.i1, q.i1));
        }
    d.walkPath = roomTour(g, plan, floorY + eyeHeight);
    const double headLow = floorY + std::max(0.5, eyeHeight - 0.5),
                 headHigh = std::min(ceilingY, floorY + eyeHeight + 0.3);
    d.headHeightRange = {headLow, std::max(headLow, headHigh)};
    return d;
}

}  // namespace cavewall::walls
