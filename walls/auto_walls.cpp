#include "walls/auto_walls.h"

#include "walls/auto_rooms.h"

#include "config/error.h"
#include "scenes/loader.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "walls/plan_io.h"
#include "walls/room_cells.h"
#include "walls/storeys.h"
#include "walls/zone_index.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>
#include <cmath>
#include <limits>
#include <optional>

namespace cavewall::walls {

namespace {

// The widest extent of a box and its thinnest axis.
struct Shape {
    int thinAxis = 1;
    double thickness = 0.0, second = 0.0;
};

Shape shapeOf(const scenes::Bounds& b) {
    const glm::dvec3 s = b.size();
    Shape shape;
    int axes[3] = {0, 1, 2};
    std::sort(axes, axes + 3, [&](int a, int c) { return s[a] < s[c] || (s[a] == s[c] && a < c); });
    shape.thinAxis = axes[0];
    shape.thickness = s[axes[0]];
    shape.second = s[axes[1]];
    return shape;
}

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

// E[ms], triangles, textures and MiB of description `d` (AutoWallsCandidate without nx, nz).
// A cell's triangles are those of the content boxes meeting its region's bounding rectangle
// (exact for the rectangular cells proposed here). `eyes` (x, y, z): the walk cost's (6.);
// empty: the floor cost (4.).
AutoWallsCandidate evaluate(const scenes::SceneDescription& d, const std::vector<scenes::Bounds>& content,
                            const std::vector<std::size_t>& contentTriangles, const AutoWallsOptions& options,
                            const std::vector<glm::dvec3>& eyes = {}) {
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

// 1.'s findings over the model's objects.
struct ModelParts {
    std::vector<std::string> structure;                               // structure objects' names, in object order
    std::vector<const scenes::Object*> verticalPlanes;                // large vertical structure planes (hall walls)
    std::vector<WallPiece> pieces;                                    // thin vertical structure boxes (5.)
    std::vector<scenes::Bounds> content;                              // every other object's box
    std::vector<std::size_t> contentTriangles;                        // and its triangles
    scenes::Bounds floorBox;                                          // the floor planes'
    double floorTop = std::numeric_limits<double>::infinity();        // the lowest floor plane's top
    double ceilingBottom = -std::numeric_limits<double>::infinity();  // the highest ceiling's bottom
};

// The description's structure patterns, over all its models.
std::vector<std::string> structurePatterns(const scenes::SceneDescription& base) {
    std::vector<std::string> patterns;
    for (const scenes::ModelFile& m : base.models)
        patterns.insert(patterns.end(), m.structureNodes.begin(), m.structureNodes.end());
    return patterns;
}

bool namedStructure(const scenes::Object& o, const std::vector<std::string>& patterns) {
    bool named = o.role == scenes::Role::Structure;
    for (const std::string& p : patterns) named = named || scenes::matchesNodePattern(o.name, p);
    return named;
}

// A large plane: thinner than planarThickness of its second extent, and each of its two long
// axes covering planarExtent of the model's (`size`).
bool largePlane(const scenes::Object& o, const Shape& s, glm::dvec3 size, const AutoWallsOptions& options) {
    if (!(s.second > 0.0 && s.thickness <= options.planarThickness * s.second)) return false;
    for (int a = 0; a < 3; ++a)
        if (a != s.thinAxis && a != 1 && o.worldBounds.size()[a] < options.planarExtent * size[a]) return false;
    if (s.thinAxis != 1 && o.worldBounds.size().y < options.planarExtent * size.y) return false;
    return true;
}

// Files structure object `o` (its shape `s`; `plane`: a large plane): a piece of real wall when
// thin and vertical; a floor or ceiling when a horizontal plane, a hall wall when a vertical one.
void addStructure(ModelParts& parts, const scenes::Object& o, const Shape& s, bool plane, const scenes::Bounds& all) {
    parts.structure.push_back(o.name);
    if (s.thinAxis != 1 && s.thickness <= 0.5 && o.worldBounds.size().y >= 0.3) {
        const scenes::Bounds& b = o.worldBounds;
        const int along = s.thinAxis == 0 ? 2 : 0;
        parts.pieces.push_back({s.thinAxis, b.centre()[s.thinAxis], b.min[along], b.max[along], b.min.y, b.max.y});
    }
    if (s.thinAxis == 1 && plane) {
        // Horizontal: below the model's middle a floor (the lowest top wins), above a ceiling
        // (the highest bottom wins).
        if (o.worldBounds.centre().y < all.centre().y) {
            parts.floorTop = std::min(parts.floorTop, o.worldBounds.max.y);
            parts.floorBox.add(o.worldBounds);
        } else {
            parts.ceilingBottom = std::max(parts.ceilingBottom, o.worldBounds.min.y);
        }
    } else if (plane) {
        parts.verticalPlanes.push_back(&o);
    }
}

// 1. Structure: named by the description's patterns, or a large plane; every other object is
// content. `all`: the scene's bounds.
ModelParts classifyObjects(const scenes::Scene& scene, const std::vector<std::string>& patterns,
                           const AutoWallsOptions& options, const scenes::Bounds& all) {
    const glm::dvec3 size = all.size();
    ModelParts parts;
    for (const scenes::Object& o : scene.objects) {
        const Shape s = shapeOf(o.worldBounds);
        const bool named = namedStructure(o, patterns);
        const bool plane = largePlane(o, s, size, options);
        if (named || plane) {
            addStructure(parts, o, s, plane, all);
            continue;
        }
        parts.content.push_back(o.worldBounds);
        parts.contentTriangles.push_back(o.mesh >= 0 && o.mesh < static_cast<int>(scene.meshes.size())
                                             ? scene.meshes[o.mesh].indices.size() / 3
                                             : 0);
    }
    return parts;
}

// floorY and ceilingY from the floor and ceiling planes, else from the model's bounds.
void setFloorAndCeiling(AutoWallsResult& result, const ModelParts& parts, const scenes::Bounds& all) {
    result.floorY = std::isfinite(parts.floorTop) ? parts.floorTop : all.min.y;
    result.ceilingY = parts.ceilingBottom > result.floorY + 1.0 ? parts.ceilingBottom : all.max.y;
    if (result.ceilingY <= result.floorY + 1e-3) result.ceilingY = result.floorY + 3.0;
}

// An (x, z) rectangle.
struct Rect {
    glm::dvec2 lo, hi;
};

// 2. Walkable rectangle: the floor planes' (else the model's), inside the hall walls; the
// model's when the hall walls leave nothing.
Rect walkableRect(const ModelParts& parts, const scenes::Bounds& all) {
    const scenes::Bounds& floorArea = parts.floorBox.empty() ? all : parts.floorBox;
    glm::dvec2 lo(floorArea.min.x, floorArea.min.z), hi(floorArea.max.x, floorArea.max.z);
    for (const scenes::Object* o : parts.verticalPlanes) {
        const scenes::Bounds& b = o->worldBounds;
        const int axis = shapeOf(b).thinAxis == 0 ? 0 : 2;  // the wall's normal axis (x or z)
        const int k = axis == 0 ? 0 : 1;
        const double c = b.centre()[axis];
        if (c < 0.5 * (lo[k] + hi[k]))
            lo[k] = std::max(lo[k], b.max[axis]);
        else
            hi[k] = std::min(hi[k], b.min[axis]);
    }
    if (hi.x - lo.x < 1e-3 || hi.y - lo.y < 1e-3) return {{all.min.x, all.min.z}, {all.max.x, all.max.z}};
    return {lo, hi};
}

// `base` with the structure found (sorted, unique names) that no pattern of it matches added to
// its first model's structure patterns.
scenes::SceneDescription withStructure(const scenes::SceneDescription& base, const std::vector<std::string>& structure,
                                       const std::vector<std::string>& patterns) {
    scenes::SceneDescription named = base;
    if (!named.models.empty()) {
        std::vector<std::string>& nodes = named.models.front().structureNodes;
        for (const std::string& s : structure)
            if (std::none_of(patterns.begin(), patterns.end(),
                             [&](const std::string& p) { return scenes::matchesNodePattern(s, p); }))
                nodes.push_back(s);
    }
    return named;
}

// What every candidate is described from and scored with.
struct CandidateInputs {
    const scenes::SceneDescription& named;  // withStructure's
    const ModelParts& parts;                // content, its triangles and the wall pieces
    const AutoWallsOptions& options;
    const std::vector<glm::dvec3>& eyes;  // the walk cost's (6.); empty: the floor cost (4.)
    double floorY = 0.0, ceilingY = 0.0, eyeHeight = 0.0;
    const StoreyRooms* rooms = nullptr;  // the storey's floor plan (5.)
};

// The candidates in the order tried, with their descriptions (index for index).
struct Proposals {
    std::vector<AutoWallsCandidate> candidates;
    std::vector<scenes::SceneDescription> descriptions;
    double limitMetres = 0.0;  // 8.: virtual wall this storey may plan
    AutoWallsLimit limit;      // what it planned and left out (eyes aside)
    int storey = 0;            // for the progress lines
};

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

// Scores `d` (4.-6.), adds it to `out` and reports it to options.progress.
AutoWallsCandidate& addCandidate(Proposals& out, const CandidateInputs& in, scenes::SceneDescription d,
                                 AutoWallsCandidate shape) {
    const auto start = std::chrono::steady_clock::now();
    const double metres = wallMetres(d);
    AutoWallsCandidate c = evaluate(d, in.parts.content, in.parts.contentTriangles, in.options, in.eyes);
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
};

// 5. The rooms of the floor plan, when it has two or more: cells cut along them
// (walls/room_cells.h), halved while over the texture budget, down to 4.
std::optional<Rooms> floorPlanRoomsOf(const CandidateInputs& in) {
    if (!in.rooms || in.rooms->plan.rooms.size() < 2) return std::nullopt;
    RoomCellOptions cellOptions;
    scenes::SceneDescription d;
    for (;; cellOptions.maxCells /= 2) {
        d = describeRooms(in.named, in.rooms->grid.grid, in.rooms->plan, in.floorY, in.ceilingY, in.eyeHeight,
                          cellOptions);
        scenes::validateSceneDescription(d, "auto walls (floor plan rooms)");
        if (cellOptions.maxCells / 2 < 4) break;
        if (evaluate(d, in.parts.content, in.parts.contentTriangles, in.options, in.eyes).withinBudget) break;
    }
    AutoWallsCandidate shape;
    shape.nx = static_cast<int>(d.cells.size());
    shape.nz = 1;
    shape.rooms = shape.floorPlan = true;
    return Rooms{std::move(d), shape};
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

// 3.-5. The grids and the rooms of one storey within out.limitMetres: the rooms' walls are
// counted first, the grids get the rest; the rooms are scored last.
void addCandidates(Proposals& out, const CandidateInputs& in, const Rect& walkable) {
    std::optional<Rooms> rooms = roomsOf(in, walkable);
    const double roomsMetres = rooms ? wallMetres(rooms->description) : 0.0;
    const bool roomsFit = rooms && roomsMetres <= kMostPerCandidate * out.limitMetres;
    addGrids(out, in, walkable, out.limitMetres - (roomsFit ? roomsMetres : 0.0));
    if (!rooms) return;
    if (!roomsFit) {
        skip(out, roomsMetres);
        return;
    }
    addCandidate(out, in, std::move(rooms->description), rooms->shape);
}

// The cheapest candidate within the budget (the first of equals; the first candidate, one cell,
// always fits), or with `preferRooms` the rooms when they are within it.
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

// The parts of the storey [floorY, ceilingY): content and wall pieces whose boxes reach into it,
// each piece cut to that range.
ModelParts storeyParts(const ModelParts& parts, double floorY, double ceilingY) {
    constexpr double kReach = 0.05;  // metres into the storey: a slab's edge is not in it
    ModelParts own;
    for (std::size_t i = 0; i < parts.content.size(); ++i)
        if (parts.content[i].max.y > floorY + kReach && parts.content[i].min.y < ceilingY - kReach) {
            own.content.push_back(parts.content[i]);
            own.contentTriangles.push_back(parts.contentTriangles[i]);
        }
    for (WallPiece p : parts.pieces)
        if (p.top > floorY + kReach && p.bottom < ceilingY - kReach) {
            p.bottom = std::max(p.bottom, floorY);
            p.top = std::min(p.top, ceilingY);
            own.pieces.push_back(p);
        }
    return own;
}

// 7.'s walkable rectangle of storey `s`: the part of `hall` (2.'s) within its floor's bounds,
// the floor's bounds when they do not meet, `hall` when the storey has no floor.
Rect storeyRect(const Storey& s, const Rect& hall) {
    if (s.floorMin.x > s.floorMax.x) return hall;
    const Rect r{glm::max(hall.lo, s.floorMin), glm::min(hall.hi, s.floorMax)};
    if (r.hi.x - r.lo.x < 1e-3 || r.hi.y - r.lo.y < 1e-3) return {s.floorMin, s.floorMax};
    return r;
}

// The floor plan of storey [floorY, ceilingY) over `walkable` (5.), its figures in `out`.
StoreyRooms storeyRooms(const scenes::Scene& scene, double floorY, double ceilingY, const Rect& walkable,
                        AutoWallsStorey& out) {
    StoreyRooms rooms = findStoreyRooms(scene, floorY, ceilingY, walkable.lo, walkable.hi);
    out.wallElements = rooms.grid.wallElements;
    out.rooms = static_cast<int>(rooms.plan.rooms.size());
    out.doorways = static_cast<int>(rooms.plan.doorways.size());
    out.exits = rooms.plan.exits;
    for (const Room& r : rooms.plan.rooms) out.roomArea += r.area;
    return rooms;
}

// Adds one storey's limits and eyes to the result's.
void addLimit(AutoWallsLimit& total, const AutoWallsLimit& one, const std::vector<glm::dvec3>& eyes, double eyeStep,
              bool onPath) {
    if (one.skipped > 0)
        total.skippedMetres = total.skipped == 0 ? one.skippedMetres : std::min(total.skippedMetres, one.skippedMetres);
    total.planned += one.planned;
    total.skipped += one.skipped;
    total.plannedMetres += one.plannedMetres;
    total.eyes += eyes.size();
    if (eyes.empty()) return;
    total.eyeStep = std::max(total.eyeStep, eyeStep);
    total.eyesWidened = total.eyesWidened || eyeStep > (onPath ? 0.25 : 0.5);
}

// The candidates of one storey (`in`) over `walkable` within `limitMetres`; the result gets
// its limits and eyes.
Proposals proposeStorey(AutoWallsResult& result, const CandidateInputs& in, const Rect& walkable, int storey,
                        double limitMetres, double eyeStep, bool onPath) {
    Proposals proposals;
    proposals.limitMetres = limitMetres;
    proposals.storey = storey;
    addCandidates(proposals, in, walkable);
    addLimit(result.limit, proposals.limit, in.eyes, eyeStep, onPath);
    return proposals;
}

// 7. Every storey of `found` (two or more) cut on its own; the proposal stacks the chosen ones.
void proposeStoreys(AutoWallsResult& result, const scenes::Scene& scene, const Storeys& found, const ModelParts& parts,
                    const scenes::SceneDescription& named, const scenes::SceneDescription& base,
                    const AutoWallsOptions& options, const Rect& hall) {
    AutoWallsOptions each = options;
    const auto storeys = static_cast<double>(found.storeys.size());
    each.textureBudgetMB = options.textureBudgetMB / storeys;
    std::vector<scenes::SceneDescription> chosen;
    for (std::size_t i = 0; i < found.storeys.size(); ++i) {
        const Storey& s = found.storeys[i];
        const ModelParts own = storeyParts(parts, s.floorY, s.ceilingY);
        const Rect walkable = storeyRect(s, hall);
        std::vector<glm::dvec3> eyes;
        double step = 0.0;
        bool onPath = base.walkPath.size() >= 2;
        if (options.walkCost) {
            const double eyeY = s.floorY + base.eyeHeight;
            eyes = costEyes(base.walkPath, walkable.lo, walkable.hi, eyeY, &step);
            std::erase_if(eyes, [&](const glm::dvec3& e) {
                return storeyAt(found.storeys, e.y - base.eyeHeight) != static_cast<int>(i);
            });
            if (eyes.empty()) {
                eyes = costEyes({}, walkable.lo, walkable.hi, eyeY, &step);
                onPath = false;
            }
        }
        AutoWallsStorey figures{s, walkable.lo, walkable.hi};
        const StoreyRooms rooms = storeyRooms(scene, s.floorY, s.ceilingY, walkable, figures);
        const CandidateInputs in{named, own, each, eyes, s.floorY, s.ceilingY, base.eyeHeight, &rooms};
        Proposals proposals =
            proposeStorey(result, in, walkable, static_cast<int>(i), options.planLimitMetres / storeys, step, onPath);
        const int pick = chooseCandidate(proposals.candidates, options.preferRooms);
        const int first = static_cast<int>(result.candidates.size());
        for (AutoWallsCandidate& c : proposals.candidates) {
            c.storey = static_cast<int>(i);
            result.candidates.push_back(c);
        }
        const int cells = static_cast<int>(proposals.descriptions[pick].cells.size());
        figures.chosen = first + pick;
        figures.cells = cells;
        result.storeys.push_back(figures);
        chosen.push_back(std::move(proposals.descriptions[pick]));
    }
    result.description = stackStoreys(chosen, found, base.eyeHeight);
    scenes::validateSceneDescription(result.description, "auto walls (storeys)");
    const AutoWallsStorey& lowest = result.storeys.front();
    result.floorY = lowest.storey.floorY;
    result.ceilingY = lowest.storey.ceilingY;
    result.floorMin = lowest.floorMin;
    result.floorMax = lowest.floorMax;
    result.chosen = lowest.chosen;
}

}  // namespace

void validateAutoWallsOptions(const AutoWallsOptions& o) {
    validatePlanOptions(o.plan);
    auto check = [](bool ok, const std::string& name, const std::string& expected, double got) {
        if (!ok)
            throw Error("auto walls: " + name + " out of range (expected " + expected + ", got " + std::to_string(got) +
                        ")");
    };
    check(std::isfinite(o.textureBudgetMB) && o.textureBudgetMB > 0.0, "texture budget", "> 0 MiB", o.textureBudgetMB);
    check(std::isfinite(o.msPerMillionTriangles) && o.msPerMillionTriangles >= 0.0, "ms per million triangles", ">= 0",
          o.msPerMillionTriangles);
    check(std::isfinite(o.msPerWallSide) && o.msPerWallSide >= 0.0, "ms per wall side", ">= 0", o.msPerWallSide);
    check(std::isfinite(o.minCellSize) && o.minCellSize > 0.0, "minimum cell size", "> 0 m", o.minCellSize);
    check(o.maxCellsPerAxis >= 1 && o.maxCellsPerAxis <= 26, "cells per axis", "1 to 26", o.maxCellsPerAxis);
    check(o.planarThickness > 0.0 && o.planarThickness < 1.0, "planar thickness", "in (0, 1)", o.planarThickness);
    check(o.planarExtent > 0.0 && o.planarExtent <= 1.0, "planar extent", "in (0, 1]", o.planarExtent);
    check(std::isfinite(o.planLimitMetres) && o.planLimitMetres > 0.0, "planning limit", "> 0 m", o.planLimitMetres);
}

AutoWallsResult proposeWalls(const scenes::Scene& scene, const scenes::SceneDescription& base,
                             const AutoWallsOptions& options, std::vector<std::string>* warnings) {
    validateAutoWallsOptions(options);
    checkWallsModel(scene, "auto walls: scene '" + scene.name + "'");
    if (warnings && (!base.realWalls.empty() || !base.walls.empty()))
        warnings->push_back("auto walls: the description's " + std::to_string(base.walls.size()) + " walls and " +
                            std::to_string(base.realWalls.size()) + " real walls are replaced (by the proposal's own)");
    AutoWallsResult result;
    const scenes::Bounds all = scene.bounds();
    const std::vector<std::string> patterns = structurePatterns(base);
    ModelParts parts = classifyObjects(scene, patterns, options, all);
    setFloorAndCeiling(result, parts, all);
    const Rect walkable = walkableRect(parts, all);
    result.floorMin = walkable.lo;
    result.floorMax = walkable.hi;
    result.structure = std::move(parts.structure);
    std::sort(result.structure.begin(), result.structure.end());
    result.structure.erase(std::unique(result.structure.begin(), result.structure.end()), result.structure.end());
    const scenes::SceneDescription named = withStructure(base, result.structure, patterns);

    // 7. More than one storey: each cut on its own.
    const Storeys found = findStoreys(horizontalFacets(scene), all.min.y, all.max.y);
    result.stairs = found.stairs;
    if (found.storeys.size() > 1) {
        proposeStoreys(result, scene, found, parts, named, base, options, walkable);
    } else {
        // 3-5. Candidates, cost and budget (6.: the walk cost's eyes).
        double step = 0.0;
        const std::vector<glm::dvec3> eyes =
            options.walkCost ? costEyes(base.walkPath, walkable.lo, walkable.hi, result.floorY + base.eyeHeight, &step)
                             : std::vector<glm::dvec3>{};
        AutoWallsStorey figures{found.storeys.front(), walkable.lo, walkable.hi};
        const StoreyRooms rooms = storeyRooms(scene, result.floorY, result.ceilingY, walkable, figures);
        const CandidateInputs in{named, parts, options, eyes, result.floorY, result.ceilingY, base.eyeHeight, &rooms};
        Proposals proposals =
            proposeStorey(result, in, walkable, 0, options.planLimitMetres, step, base.walkPath.size() >= 2);
        result.candidates = std::move(proposals.candidates);
        result.chosen = chooseCandidate(result.candidates, options.preferRooms);
        result.description = std::move(proposals.descriptions[result.chosen]);
        figures.storey.floorY = result.floorY;  // 1.'s structure planes, as before storeys were found
        figures.storey.ceilingY = result.ceilingY;
        figures.chosen = result.chosen;
        figures.cells = static_cast<int>(result.description.cells.size());
        result.storeys.push_back(figures);
    }
    const std::vector<glm::dvec3> eyes =
        options.walkCost ? costEyes(base.walkPath, walkable.lo, walkable.hi, result.floorY + base.eyeHeight)
                         : std::vector<glm::dvec3>{};
    if (!base.walls.empty()) result.given = evaluate(base, parts.content, parts.contentTriangles, options, eyes);
    return result;
}

}  // namespace cavewall::walls
