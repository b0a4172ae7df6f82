#include "walls/auto_walls.h"

#include "config/error.h"
#include "scenes/loader.h"
#include "scenes/region.h"
#include "scenes/scene_description_io.h"
#include "walls/auto_rooms.h"
#include "walls/auto_walls_candidates.h"
#include "walls/room_cells.h"
#include "walls/room_tour.h"
#include "walls/storeys.h"
#include "walls/void_walls.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::walls {

namespace {

using detail::addCandidates;
using detail::CandidateInputs;
using detail::chooseCandidate;
using detail::evaluate;
using detail::ModelParts;
using detail::Proposals;
using detail::Rect;

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

// Walks between storeys over each storey's rooms and doorways (walls/room_tour.h), where the
// storey has rooms and its chosen cells hold every point of the walk at eye height.
FloorRoute roomsRoute(const std::vector<StoreyRooms>& plans, const std::vector<scenes::SceneDescription>& chosen,
                      double eyeHeight) {
    return [&plans, &chosen, eyeHeight](int storey, glm::dvec3 from, glm::dvec3 to) -> std::vector<glm::dvec3> {
        const StoreyRooms& rooms = plans[storey];
        std::vector<glm::dvec3> walk;
        if (rooms.plan.rooms.empty()) return walk;
        for (const glm::dvec2& p : roomRoute(rooms.grid.grid, rooms.plan, {from.x, from.z}, {to.x, to.z})) {
            walk.push_back({p.x, from.y, p.y});
            if (scenes::findCell(chosen[storey].cells, walk.back() + glm::dvec3(0.0, eyeHeight, 0.0)) < 0) return {};
        }
        if (!walk.empty()) walk.back() = to;
        return walk;
    };
}

// 7. Every storey of `found` (two or more) cut on its own; the proposal stacks the chosen ones.
void proposeStoreys(AutoWallsResult& result, const scenes::Scene& scene, const Storeys& found, const ModelParts& parts,
                    const scenes::SceneDescription& named, const scenes::SceneDescription& base,
                    const AutoWallsOptions& options, const Rect& hall) {
    AutoWallsOptions each = options;
    const auto storeys = static_cast<double>(found.storeys.size());
    each.textureBudgetMB = options.textureBudgetMB / storeys;
    std::vector<scenes::SceneDescription> chosen;
    std::vector<StoreyRooms> plans;  // those with rooms; empty for the others (a grid can be large)
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
        StoreyRooms rooms = storeyRooms(scene, s.floorY, s.ceilingY, walkable, figures);
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
        plans.push_back(rooms.plan.rooms.empty() ? StoreyRooms{} : std::move(rooms));
    }
    result.description = stackStoreys(chosen, found, base.eyeHeight, roomsRoute(plans, chosen, base.eyeHeight));
    result.wallsRaised = raiseWallsUnderVoids(result.description, scene, found.storeys);
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
