#include "walls/rooms.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>

namespace cavewall::walls {

namespace {

constexpr int kNeighbours[4][2] = {{1, 0}, {-1, 0}, {0, 1}, {0, -1}};

// 4-connected components of the cells where `member` is set: per cell its component or -1,
// and the cells of each component.
struct Components {
    std::vector<int> of;
    std::vector<std::vector<int>> cells;
};

Components components(const FloorGrid& g, const std::vector<std::uint8_t>& member) {
    Components out;
    out.of.assign(member.size(), -1);
    for (int start = 0; start < static_cast<int>(member.size()); ++start) {
        if (!member[start] || out.of[start] >= 0) continue;
        const int id = static_cast<int>(out.cells.size());
        std::vector<int> cells{start};
        out.of[start] = id;
        for (std::size_t next = 0; next < cells.size(); ++next) {
            const int i = cells[next] % g.nx, k = cells[next] / g.nx;
            for (const auto& n : kNeighbours) {
                if (!g.inside(i + n[0], k + n[1])) continue;
                const int c = g.index(i + n[0], k + n[1]);
                if (member[c] && out.of[c] < 0) {
                    out.of[c] = id;
                    cells.push_back(c);
                }
            }
        }
        out.cells.push_back(std::move(cells));
    }
    return out;
}

// 1. Free components lying wholly within sliverWidth / 2 of a wall become wall.
std::vector<std::uint8_t> fillWallInteriors(const FloorGrid& g, const RoomOptions& options) {
    std::vector<std::uint8_t> wall = g.wall;
    const std::vector<float> distance = chamferDistance(g, wall);
    std::vector<std::uint8_t> free(wall.size());
    for (std::size_t c = 0; c < wall.size(); ++c) free[c] = !wall[c];
    const float limit = static_cast<float>(0.5 * options.sliverWidth / g.cellSize);
    for (const std::vector<int>& cells : components(g, free).cells) {
        const bool sliver = std::all_of(cells.begin(), cells.end(), [&](int c) { return distance[c] <= limit; });
        if (sliver)
            for (int c : cells) wall[c] = 1;
    }
    return wall;
}

// 2. Per cell the narrowest gap (metres) it lies in along a row or a column, 0 for none.
std::vector<float> gapWidths(const FloorGrid& g, const std::vector<std::uint8_t>& wall, const RoomOptions& options) {
    std::vector<float> gap(wall.size(), 0.0f);
    const int maxCells = static_cast<int>(std::floor(options.maxDoorWidth / g.cellSize + 1e-6));
    auto scan = [&](int lines, int length, auto at) {
        for (int line = 0; line < lines; ++line) {
            int last = -1;  // the last wall cell along this line
            for (int s = 0; s < length; ++s) {
                if (!wall[at(line, s)]) continue;
                const int run = s - last - 1;
                if (last >= 0 && run > 0 && run <= maxCells) {
                    const auto width = static_cast<float>(run * g.cellSize);
                    for (int t = last + 1; t < s; ++t) {
                        float& w = gap[at(line, t)];
                        w = w > 0.0f ? std::min(w, width) : width;
                    }
                }
                last = s;
            }
        }
    };
    scan(g.nz, g.nx, [&](int k, int i) { return g.index(i, k); });
    scan(g.nx, g.nz, [&](int i, int k) { return g.index(i, k); });
    return gap;
}

// A closed opening (3.): its cells, width and extent.
struct Opening {
    std::vector<int> cells;
    double width = 0.0;
    glm::dvec2 centroid{0.0};
    bool alongX = true;
};

std::vector<Opening> closedOpenings(const FloorGrid& g, const std::vector<float>& gap, const RoomOptions& options) {
    std::vector<std::uint8_t> inGap(gap.size());
    for (std::size_t c = 0; c < gap.size(); ++c) inGap[c] = gap[c] > 0.0f;
    const double cellArea = g.cellSize * g.cellSize;
    const double maxArea = options.maxDoorWidth * options.maxWallThickness + 1e-9;
    std::vector<Opening> out;
    for (std::vector<int>& cells : components(g, inGap).cells) {
        if (static_cast<double>(cells.size()) * cellArea > maxArea) continue;
        Opening o;
        glm::ivec2 lo(g.nx, g.nz), hi(-1);
        for (int c : cells) {
            const glm::ivec2 ik(c % g.nx, c / g.nx);
            lo = glm::min(lo, ik);
            hi = glm::max(hi, ik);
            o.width = std::max(o.width, static_cast<double>(gap[c]));
            o.centroid += g.centre(ik.x, ik.y);
        }
        o.centroid /= static_cast<double>(cells.size());
        o.alongX = hi.x - lo.x >= hi.y - lo.y;
        o.cells = std::move(cells);
        out.push_back(std::move(o));
    }
    return out;
}

Room describeRoom(const FloorGrid& g, const std::vector<int>& cells, const std::vector<float>& depth) {
    Room r;
    r.area = static_cast<double>(cells.size()) * g.cellSize * g.cellSize;
    r.lo = glm::dvec2(1e300);
    r.hi = glm::dvec2(-1e300);
    int deepest = cells.front();
    for (int c : cells) {
        const glm::dvec2 lo = g.origin + g.cellSize * glm::dvec2(c % g.nx, c / g.nx);
        r.lo = glm::min(r.lo, lo);
        r.hi = glm::max(r.hi, lo + g.cellSize);
        if (depth[c] > depth[deepest]) deepest = c;
    }
    r.inner = g.centre(deepest % g.nx, deepest / g.nx);
    return r;
}

// The component's edges (between its cells and others): all, and those leading to free cells
// without floor or off the grid.
struct Edges {
    int all = 0, open = 0;
};

Edges edgesOf(const FloorGrid& g, const std::vector<int>& cells, const std::vector<int>& of,
              const std::vector<std::uint8_t>& barrier) {
    const int self = of[cells.front()];
    int edges = 0, open = 0;
    for (int c : cells) {
        const int i = c % g.nx, k = c / g.nx;
        for (const auto& n : kNeighbours) {
            const bool inside = g.inside(i + n[0], k + n[1]);
            const int d = inside ? g.index(i + n[0], k + n[1]) : -1;
            if (inside && of[d] == self) continue;
            ++edges;
            if (!inside || (!barrier[d] && !g.floor[d])) ++open;
        }
    }
    return {edges, open};
}

// 4. Rooms: floor components off the barrier of at least minRoomArea, not outside.
void findRoomCells(FloorPlan& plan, const FloorGrid& g, const RoomOptions& options) {
    std::vector<std::uint8_t> open(g.floor.size());
    for (std::size_t c = 0; c < open.size(); ++c) open[c] = g.floor[c] && !plan.barrier[c];
    std::vector<std::uint8_t> closed(open.size());
    for (std::size_t c = 0; c < open.size(); ++c) closed[c] = !open[c];
    const std::vector<float> depth = chamferDistance(g, closed);
    plan.room.assign(open.size(), -1);
    const double cellArea = g.cellSize * g.cellSize;
    const Components parts = components(g, open);
    for (const std::vector<int>& cells : parts.cells) {
        if (static_cast<double>(cells.size()) * cellArea < options.minRoomArea - 1e-9) continue;
        const Edges edges = edgesOf(g, cells, parts.of, plan.barrier);
        if (edges.open > options.maxOpenEdgeShare * edges.all || edges.open * g.cellSize > options.maxOpenEdge)
            continue;
        for (int c : cells) plan.room[c] = static_cast<int>(plan.rooms.size());
        plan.rooms.push_back(describeRoom(g, cells, depth));
    }
}

// 5. What the opening joins: a doorway, an exit or nothing.
void classifyOpening(FloorPlan& plan, const FloorGrid& g, const Opening& o, const RoomOptions& options) {
    std::map<int, int> touching;  // room -> neighbouring cells
    bool outside = false;
    for (int c : o.cells) {
        const int i = c % g.nx, k = c / g.nx;
        for (const auto& n : kNeighbours) {
            if (!g.inside(i + n[0], k + n[1])) {
                outside = true;
                continue;
            }
            const int d = g.index(i + n[0], k + n[1]);
            if (plan.room[d] >= 0) ++touching[plan.room[d]];
            if (!plan.barrier[d] && !g.floor[d]) outside = true;
        }
    }
    if (o.width < options.minDoorWidth - 1e-9) return;
    if (touching.size() == 1 && outside) ++plan.exits;
    if (touching.size() < 2) return;
    std::vector<std::pair<int, int>> byContact;  // (-contact, room): most contact first, then lowest room
    for (const auto& [r, contact] : touching) byContact.push_back({-contact, r});
    std::sort(byContact.begin(), byContact.end());
    Doorway d;
    d.position = o.centroid;
    d.width = o.width;
    d.alongX = o.alongX;
    d.rooms = {std::min(byContact[0].second, byContact[1].second), std::max(byContact[0].second, byContact[1].second)};
    for (int c : o.cells) plan.opening[c] = static_cast<int>(plan.doorways.size());
    plan.doorways.push_back(d);
}

}  // namespace

void validateRoomOptions(const RoomOptions& o) {
    auto check = [](bool ok, const std::string& name, const std::string& expected, double got) {
        if (!ok)
            throw Error("rooms: " + name + " out of range (expected " + expected + ", got " + std::to_string(got) +
                        ")");
    };
    check(std::isfinite(o.minDoorWidth) && o.minDoorWidth > 0.0, "minimum door width", "> 0 m", o.minDoorWidth);
    check(std::isfinite(o.maxDoorWidth) && o.maxDoorWidth >= o.minDoorWidth, "maximum door width",
          ">= the minimum door width", o.maxDoorWidth);
    check(std::isfinite(o.maxWallThickness) && o.maxWallThickness > 0.0, "maximum wall thickness", "> 0 m",
          o.maxWallThickness);
    check(std::isfinite(o.sliverWidth) && o.sliverWidth >= 0.0, "sliver width", ">= 0 m", o.sliverWidth);
    check(std::isfinite(o.minRoomArea) && o.minRoomArea > 0.0, "minimum room area", "> 0 m²", o.minRoomArea);
    check(o.maxOpenEdgeShare >= 0.0 && o.maxOpenEdgeShare <= 1.0, "maximum open edge share", "in [0, 1]",
          o.maxOpenEdgeShare);
    check(std::isfinite(o.maxOpenEdge) && o.maxOpenEdge >= 0.0, "maximum open edge", ">= 0 m", o.maxOpenEdge);
}

FloorPlan findRooms(const FloorGrid& g, const RoomOptions& options) {
    validateRoomOptions(options);
    FloorPlan plan;
    plan.barrier = fillWallInteriors(g, options);
    const std::vector<float> gap = gapWidths(g, plan.barrier, options);
    const std::vector<Opening> openings = closedOpenings(g, gap, options);
    for (const Opening& o : openings)
        for (int c : o.cells) plan.barrier[c] = 1;
    findRoomCells(plan, g, options);
    plan.opening.assign(plan.room.size(), -1);
    for (const Opening& o : openings) classifyOpening(plan, g, o, options);
    return plan;
}

}  // namespace cavewall::walls
