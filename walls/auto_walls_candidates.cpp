#include "walls/auto_walls_candidates.h"

#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "walls/plan_io.h"
#include "walls/room_tour.h"
#include "walls/zone_index.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

namespace cavewall::walls::detail {

namespace {

double overlap1d(double a0, double a1, double b0, double b1) {
    return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}

// Cuts `count` cells over [lo, hi], each interior cut moved within a quarter cell to where the
// fewest content boxes straddle it.
std::vector<double> chooseCuts(double lo, double hi, int count, const std::vector<scenes::Bounds>& boxes, int axis) {
    std::vector<double> cuts{lo};
    const double width = (hi - lo) / count;
    for (int k = 1; k < count; ++k) {
        const double centre = lo + k * width;
        double best = centre;
        std::size_t bestStraddling = std::numeric_limits<std::size_t>::max();
        const int steps = static_cast<int>(std::floor(width / 4.0 / 0.05));
        for (int i = 0; i <= 2 * steps; ++i) {
            // Centre first, then alternately further out: ties keep the cut nearest the even split.
            const int offset = (i % 2 == 0 ? 1 : -1) * ((i + 1) / 2);
            const double x = centre + 0.05 * offset;
            std::size_t straddling = 0;
            for (const scenes::Bounds& b : boxes)
                if (b.min[axis] < x - 1e-9 && b.max[axis] > x + 1e-9) ++straddling;
            if (straddling < bestStraddling) {
                bestStraddling = straddling;
                best = x;
            }
        }
        cuts.push_back(best);
    }
    cuts.push_back(hi);
    return cuts;
}

struct Grid {
    std::vector<double> xs, zs;  // cut positions, first and last are the floor's edges
};

scenes::SceneDescription describe(const scenes::SceneDescription& base, const Grid& g, double floorY, double ceilingY,
                                  double eyeHeight) {
    scenes::SceneDescription d = base;
    d.cells.clear();
    d.walls.clear();
    d.realWalls.clear();
    d.wallPath.clear();
    const int nx = static_cast<int>(g.xs.size()) - 1, nz = static_cast<int>(g.zs.size()) - 1;
    auto index = [&](int i, int k) { return k * nx + i; };
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) {
            scenes::Cell c;
            c.name.assign(1, static_cast<char>('A' + std::min(k, 25)));
            c.name += std::to_string(i + 1);
            c.floorY = floorY;
            // Counter-clockwise seen from above (+x towards -z), as the plant's cells.
            c.region = {{g.xs[i], g.zs[k + 1]}, {g.xs[i + 1], g.zs[k + 1]}, {g.xs[i + 1], g.zs[k]}, {g.xs[i], g.zs[k]}};
            d.cells.push_back(std::move(c));
        }
    auto centre = [&](int cell) {
        glm::dvec2 c(0.0);
        for (const glm::dvec2& p : d.cells[cell].region) c += p;
        return c / static_cast<double>(d.cells[cell].region.size());
    };
    for (int k = 0; k < nz; ++k)
        for (int i = 0; i < nx; ++i) {
            const int here = index(i, k);
            if (i + 1 < nx) {
                const int there = index(i + 1, k);
                scenes::VirtualWall w =
                    wallBetween({g.xs[i + 1], g.zs[k]}, {g.xs[i + 1], g.zs[k + 1]}, floorY, ceilingY, centre(here));
                w.name = d.cells[here].name + "|" + d.cells[there].name;
                w.cells = {here, there};
                d.walls.push_back(w);
            }
            if (k + 1 < nz) {
                const int there = index(i, k + 1);
                scenes::VirtualWall w =
                    wallBetween({g.xs[i], g.zs[k + 1]}, {g.xs[i + 1], g.zs[k + 1]}, floorY, ceilingY, centre(here));
                w.name = d.cells[here].name + "|" + d.cells[there].name;
                w.cells = {here, there};
                d.walls.push_back(w);
            }
        }
    // A loop a quarter of the way in from the floor's edges, at eye height.
    const double x0 = g.xs.front(), x1 = g.xs.back(), z0 = g.zs.front(), z1 = g.zs.back();
    const double ix = 0.25 * (x1 - x0), iz = 0.25 * (z1 - z0), y = floorY + eyeHeight;
    d.walkPath = {{x0 + ix, y, z0 + iz},
                  {x1 - ix, y, z0 + iz},
                  {x1 - ix, y, z1 - iz},
                  {x0 + ix, y, z1 - iz},
                  {x0 + ix, y, z0 + iz}};
    const double headLow = floorY + std::max(0.5, eyeHeight - 0.5),
                 headHigh = std::min(ceilingY, floorY + eyeHeight + 0.3);
    d.headHeightRange = {headLow, std::max(headLow, headHigh)};
    return d;
}

// The triangles drawn from `eye` in `cell`: the cell's, plus those of every neighbour whose
// zone holding the eye draws it as geometry (the planner's own zones).
double drawnFrom(const glm::dvec3& eye, int cell, const std::optional<Plan>& plan,
                 const std::optional<ZoneIndex>& index, const std::vector<double>& cellTriangles) {
    double drawn = cellTriangles[cell];
    if (plan && index)
        for (const WallSide& side : plan->sides) {
            if (side.cell != cell) continue;
            const int z = index->find(cell, side.wall, {eye.x, eye.z});
            if (z < 0) continue;
            const Zone& zone = plan->zones[z];
            if (zone.kind != ZoneKind::Geometry && !(zone.kind == ZoneKind::Blend && zone.mixesGeometry)) continue;
            const std::array<int, 2>& both = plan->walls[side.wall].cells;
            const int behind = both[0] == cell ? both[1] : both[0];
            if (behind >= 0) drawn += cellTriangles[behind];
        }
    return drawn;
}

// The walk cost (6.): `c`'s E[ms] and meanCellTriangles become the means over the eyes in a
// cell (unchanged when there are none). `cellTriangles`, `cellSides`: per cell of `d`.
void applyWalkCost(AutoWallsCandidate& c, const scenes::SceneDescription& d, const std::optional<Plan>& plan,
                   const std::vector<double>& cellTriangles, const std::vector<int>& cellSides,
                   const AutoWallsOptions& options, const std::vector<glm::dvec3>& eyes) {
    double ms = 0.0, triangles = 0.0;
    int counted = 0;
    std::optional<ZoneIndex> index;
    if (plan) index.emplace(*plan);
    for (const glm::dvec3& eye : eyes) {
        const int cell = scenes::findCell(d.cells, eye);
        if (cell < 0) continue;
        const double drawn = drawnFrom(eye, cell, plan, index, cellTriangles);
        ms += options.msPerMillionTriangles * drawn / 1e6 + options.msPerWallSide * cellSides[cell];
        triangles += drawn;
        ++counted;
    }
    if (counted > 0) {
        c.expectedMs = ms / counted;
        c.meanCellTriangles = triangles / counted;
    }
}

double wallMetres(const scenes::SceneDescription& d) {
    double metres = 0.0;
    for (const scenes::VirtualWall& w : d.walls) metres += glm::length(w.lowerRight - w.lowerLeft);
    return metres;
}

// Not planned: over 8.'s limit.
void skip(Proposals& out, double metres) {
    out.limit.skippedMetres = out.limit.skipped == 0 ? metres : std::min(out.limit.skippedMetres, metres);
    ++out.limit.skipped;
}

// Scores `d` (4.-6.; `scored`: its score, evaluated already), adds it to `out` and reports it
// to options.progress.
AutoWallsCandidate& addCandidate(Proposals& out, const CandidateInputs& in, scenes::SceneDescription d,
                                 AutoWallsCandidate shape, const std::optional<AutoWallsCandidate>& scored = {}) {
    const auto start = std::chrono::steady_clock::now();
    const double metres = wallMetres(d);
    AutoWallsCandidate c =
        scored ? *scored : evaluate(d, in.parts.content, in.parts.contentTriangles, in.options, in.eyes);
    c.nx = shape.nx;
    c.nz = shape.nz;
    c.rooms = shape.rooms;
    c.floorPlan = shape.floorPlan;
    for (const scenes::VirtualWall& w : d.walls) ++(w.kind == scenes::WallKind::Portal ? c.portals : c.virtualWalls);
    if (!c.rooms) c.portals = c.virtualWalls = 0;
    ++out.limit.planned;
    out.limit.plannedMetres += metres;
    if (in.options.progress) {
        char line[200];
        std::snprintf(line, sizeof line,
                      "storey %d: %s %d x %d (%zu cells, %.0f m of virtual wall): %d textures, %.1f s", out.storey,
                      c.rooms ? "rooms" : "grid", c.nx, c.nz, d.cells.size(), metres, c.textures,
                      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        in.options.progress(line);
    }
    out.candidates.push_back(c);
    out.descriptions.push_back(std::move(d));
    return out.candidates.back();
}

// 3.-4. Every grid of nx x nz cells over `walkable` within 8.'s limit (`limitMetres`), scored;
// a row of nz stops at its first candidate over the budget.
void addGrids(Proposals& out, const CandidateInputs& in, const Rect& walkable, double limitMetres) {
    const AutoWallsOptions& options = in.options;
    const glm::dvec2 size = walkable.hi - walkable.lo;
    const int maxX = std::clamp(static_cast<int>(size.x / options.minCellSize), 1, options.maxCellsPerAxis);
    const int maxZ = std::clamp(static_cast<int>(size.y / options.minCellSize), 1, options.maxCellsPerAxis);
    const std::vector<bool> planned = gridsWithinLimit(maxX, maxZ, size, limitMetres);
    for (int nx = 1; nx <= maxX; ++nx)
        for (int nz = 1; nz <= maxZ; ++nz) {
            if (!planned[(nx - 1) * maxZ + (nz - 1)]) {
                skip(out, gridWallMetres(nx, nz, size));
                continue;
            }
            Grid g{chooseCuts(walkable.lo.x, walkable.hi.x, nx, in.parts.content, 0),
                   chooseCuts(walkable.lo.y, walkable.hi.y, nz, in.parts.content, 2)};
            scenes::SceneDescription d = describe(in.named, g, in.floorY, in.ceilingY, in.eyeHeight);
            scenes::validateSceneDescription(d, "auto walls");
            AutoWallsCandidate shape;
            shape.nx = nx;
            shape.nz = nz;
            // More cells along z only add walls and textures: the rest of this row is over too.
            if (!addCandidate(out, in, std::move(d), shape).withinBudget) break;
        }
}

// 5. The rooms: a grid cut along the lines of real walls, its boundaries on them portals; none
// when there are no such lines. nx and nz: its grid's.
struct Rooms {
    scenes::SceneDescription description;
    AutoWallsCandidate shape;
    std::optional<AutoWallsCandidate> scored{};  // its score, when evaluated already
};

// 5. The rooms of the floor plan, when it has two or more: cells cut along them
// (walls/room_cells.h), halved while over the texture budget, down to 4.
std::optional<Rooms> floorPlanRoomsOf(const CandidateInputs& in) {
    if (!in.rooms || in.rooms->plan.rooms.size() < 2) return std::nullopt;
    RoomCellOptions cellOptions;
    scenes::SceneDescription d;
    std::optional<AutoWallsCandidate> scored;
    for (;; cellOptions.maxCells /= 2) {
        d = describeRooms(in.named, in.rooms->grid.grid, in.rooms->plan, in.floorY, in.ceilingY, in.eyeHeight,
                          cellOptions);
        scenes::validateSceneDescription(d, "auto walls (floor plan rooms)");
        if (cellOptions.maxCells / 2 < 4) break;
        scored = evaluate(d, in.parts.content, in.parts.contentTriangles, in.options, in.eyes);
        if (scored->withinBudget) break;
        scored.reset();
    }
    AutoWallsCandidate shape;
    shape.nx = static_cast<int>(d.cells.size());
    shape.nz = 1;
    shape.rooms = shape.floorPlan = true;
    return Rooms{std::move(d), shape, std::move(scored)};
}

std::optional<Rooms> roomsOf(const CandidateInputs& in, const Rect& walkable) {
    const std::vector<WallPiece>& pieces = in.parts.pieces;
    const std::vector<double> xLines =
        wallLines(pieces, 0, walkable.lo.x, walkable.hi.x, walkable.hi.y - walkable.lo.y, in.floorY);
    const std::vector<double> zLines =
        wallLines(pieces, 2, walkable.lo.y, walkable.hi.y, walkable.hi.x - walkable.lo.x, in.floorY);
    if (xLines.empty() && zLines.empty()) return floorPlanRoomsOf(in);
    Grid g{{walkable.lo.x}, {walkable.lo.y}};
    g.xs.insert(g.xs.end(), xLines.begin(), xLines.end());
    g.zs.insert(g.zs.end(), zLines.begin(), zLines.end());
    g.xs.push_back(walkable.hi.x);
    g.zs.push_back(walkable.hi.y);
    scenes::SceneDescription d = describe(in.named, g, in.floorY, in.ceilingY, in.eyeHeight);
    makeRooms(d, pieces, in.floorY, in.ceilingY);
    scenes::validateSceneDescription(d, "auto walls (rooms)");
    AutoWallsCandidate shape;
    shape.nx = static_cast<int>(g.xs.size()) - 1;
    shape.nz = static_cast<int>(g.zs.size()) - 1;
    shape.rooms = true;
    return Rooms{std::move(d), shape};
}

}  // namespace

AutoWallsCandidate evaluate(const scenes::SceneDescription& d, const std::vector<scenes::Bounds>& content,
                            const std::vector<std::size_t>& contentTriangles, const AutoWallsOptions& options,
                            const std::vector<glm::dvec3>& eyes) {
    AutoWallsCandidate c;
    double area = 0.0;
    for (const scenes::Cell& cell : d.cells) area += std::abs(scenes::regionArea(cell.region));
    std::vector<double> cellTriangles(d.cells.size(), 0.0);
    std::vector<int> cellSides(d.cells.size(), 0);
    for (std::size_t i = 0; i < d.cells.size(); ++i) {
        const scenes::Cell& cell = d.cells[i];
        glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
        for (const glm::dvec2& p : cell.region) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        const double share = area > 0.0 ? std::abs(scenes::regionArea(cell.region)) / area : 0.0;
        double triangles = 0.0;
        for (std::size_t o = 0; o < content.size(); ++o)
            if (overlap1d(content[o].min.x, content[o].max.x, lo.x, hi.x) > 0.0 &&
                overlap1d(content[o].min.z, content[o].max.z, lo.y, hi.y) > 0.0)
                triangles += static_cast<double>(contentTriangles[o]);
        int sides = 0;
        for (const scenes::VirtualWall& w : d.walls)
            sides += (w.cells[0] == static_cast<int>(i)) + (w.cells[1] == static_cast<int>(i));
        cellTriangles[i] = triangles;
        cellSides[i] = sides;
        c.meanCellTriangles += share * triangles;
        c.expectedMs += share * (options.msPerMillionTriangles * triangles / 1e6 + options.msPerWallSide * sides);
    }
    std::optional<Plan> plan;
    if (!d.walls.empty()) {
        plan = planZones(d, options.plan);
        c.textures = static_cast<int>(plan->textures.size());
        c.textureMB = planTotals(*plan).gpuBytes / (1024.0 * 1024.0);
    }
    c.withinBudget = c.textureMB <= options.textureBudgetMB;
    if (!eyes.empty()) applyWalkCost(c, d, plan, cellTriangles, cellSides, options, eyes);
    return c;
}

namespace {

// 3.-5. without the floor plan's walk.
void addEveryCandidate(Proposals& out, const CandidateInputs& in, const Rect& walkable) {
    std::optional<Rooms> rooms = roomsOf(in, walkable);
    const double roomsMetres = rooms ? wallMetres(rooms->description) : 0.0;
    const bool roomsFit = rooms && roomsMetres <= kMostPerCandidate * out.limitMetres;
    addGrids(out, in, walkable, out.limitMetres - (roomsFit ? roomsMetres : 0.0));
    if (!rooms) return;
    if (!roomsFit) {
        skip(out, roomsMetres);
        return;
    }
    addCandidate(out, in, std::move(rooms->description), rooms->shape, rooms->scored);
}

// The floor plan's room tour (walls/room_tour.h) becomes every grid candidate's walk when the
// plan has doorways (a grid's loop crosses walls there): the rooms its cells hold (the grids
// cover one rectangle, `walkable`), when that tour leaves its first room.
void walkTheRooms(Proposals& out, const CandidateInputs& in, const Rect& walkable) {
    if (!in.rooms || in.rooms->plan.doorways.empty()) return;
    const auto holds = [&](glm::dvec2 p) {
        return p.x >= walkable.lo.x && p.x <= walkable.hi.x && p.y >= walkable.lo.y && p.y <= walkable.hi.y;
    };
    const StoreyRooms& rooms = *in.rooms;
    const std::vector<glm::dvec3> tour =
        roomTour(rooms.grid.grid, rooms.plan, in.floorY + in.eyeHeight, RoomTourOptions{}, holds);
    if (tour.size() < 2 || !holds({tour.front().x, tour.front().z})) return;
    for (std::size_t n = 0; n < out.descriptions.size(); ++n) {
        scenes::SceneDescription& d = out.descriptions[n];
        if (out.candidates[n].floorPlan) continue;  // its own tour already
        const bool held = std::all_of(tour.begin(), tour.end(),
                                      [&](const glm::dvec3& p) { return scenes::findCell(d.cells, p) >= 0; });
        if (held) d.walkPath = tour;
    }
}

}  // namespace

void addCandidates(Proposals& out, const CandidateInputs& in, const Rect& walkable) {
    addEveryCandidate(out, in, walkable);
    walkTheRooms(out, in, walkable);
}

int chooseCandidate(const std::vector<AutoWallsCandidate>& candidates, bool preferRooms) {
    int chosen = 0;
    for (std::size_t i = 1; i < candidates.size(); ++i) {
        const AutoWallsCandidate& c = candidates[i];
        const AutoWallsCandidate& best = candidates[chosen];
        if (c.withinBudget && c.expectedMs < best.expectedMs) chosen = static_cast<int>(i);
    }
    if (preferRooms)
        for (std::size_t i = 0; i < candidates.size(); ++i)
            if (candidates[i].rooms && candidates[i].withinBudget) chosen = static_cast<int>(i);
    return chosen;
}

}  // namespace cavewall::walls::detail
