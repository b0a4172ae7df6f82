// validateSceneDescription: rules that span fields. Messages: "<source>: <path>: what (expected
// ..., got ...)", with JSON-like paths so they point into scene.json.
#include "scenes/scene_description_io.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "scenes/region.h"

#include <cmath>
#include <utility>

namespace cavewall::scenes {
namespace {

using config::formatNumber;

std::string fmt(glm::dvec3 v) {
    return "(" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + ")";
}

struct Checker {
    const SceneDescription& d;
    const std::string& source;

    [[noreturn]] void fail(const std::string& where, const std::string& what) const {
        throw Error(source + ": " + where + ": " + what);
    }

    // Walls and real walls: a non-degenerate rectangle in a vertical plane.
    void checkQuad(const std::string& where, glm::dvec3 ll, glm::dvec3 lr, glm::dvec3 ul) const {
        const glm::dvec3 right = lr - ll, up = ul - ll;
        const double area = glm::length(glm::cross(right, up));
        if (!(area > 1e-9))
            fail(where,
                 "corners are collinear or repeated (expected a non-zero area, got " + formatNumber(area) + " m²)");
        const double cosAngle = glm::dot(right, up) / (glm::length(right) * glm::length(up));
        if (std::abs(cosAngle) > 1e-6)
            fail(where, "not a rectangle (expected a right angle at lowerLeft, got " +
                            formatNumber(glm::degrees(std::acos(std::clamp(cosAngle, -1.0, 1.0)))) + "°)");
        const glm::dvec3 normal = glm::normalize(glm::cross(right, up));
        if (std::abs(normal.y) > 1e-6)
            fail(where, "not vertical (expected a normal with no vertical component, got normal " + fmt(normal) + ")");
        if (up.y <= 0.0)
            fail(where,
                 "upperLeft is not above lowerLeft (expected a positive height, got " + formatNumber(up.y) + " m)");
    }

    void checkCell(std::size_t i) const {
        const Cell& c = d.cells[i];
        const std::string where = "cells[" + std::to_string(i) + "].region";
        if (c.region.size() < 3)
            fail(where, "expected a polygon of at least 3 points, got " + std::to_string(c.region.size()));
        const double area = regionArea(c.region);
        if (std::abs(area) < 1e-6)
            fail(where, "degenerate polygon (expected a non-zero area, got " + formatNumber(std::abs(area)) + " m²)");
        if (area < 0.0) fail(where, "clockwise seen from above (expected counter-clockwise: from +x towards -z)");
        if (int bad = firstNonConvexCorner(c.region); bad >= 0)
            fail(where, "not convex (expected every corner to turn left seen from above, got a right turn at point " +
                            std::to_string(bad) + ")");
        for (std::size_t j = 0; j < i; ++j) {
            if (std::abs(d.cells[j].floorY - c.floorY) > 1e-6) continue;  // different storeys may overlap in plan
            const double overlap = overlapArea(c.region, d.cells[j].region);
            if (overlap > 1e-6)
                fail("cells[" + std::to_string(i) + "]",
                     "overlaps cells[" + std::to_string(j) + "] '" + d.cells[j].name +
                         "' (expected cells that at most touch, got " + formatNumber(overlap) + " m² in common)");
        }
    }

    void checkWall(std::size_t i) const {
        const VirtualWall& w = d.walls[i];
        const std::string where = "walls[" + std::to_string(i) + "]";
        checkQuad(where, w.lowerLeft, w.lowerRight, w.upperLeft);
        const int n = static_cast<int>(d.cells.size());
        for (int k = 0; k < 2; ++k)
            if (w.cells[k] < 0 || w.cells[k] >= n)
                fail(where + ".cells[" + std::to_string(k) + "]", "cell " + std::to_string(w.cells[k]) +
                                                                      " does not exist (expected < " +
                                                                      std::to_string(n) + " cells)");
        if (w.cells[0] == w.cells[1])
            fail(where + ".cells", "names the same cell twice (expected two different cells, got '" +
                                       d.cells[w.cells[0]].name + "' twice)");
        // A wall joins its cells: its footprint must touch both regions.
        for (int k = 0; k < 2; ++k) {
            const Cell& cell = d.cells[w.cells[k]];
            const double gap =
                segmentRegionDistance({w.lowerLeft.x, w.lowerLeft.z}, {w.lowerRight.x, w.lowerRight.z}, cell.region);
            if (gap > kMaxWallCellGap)
                fail(where, "'" + w.name + "' is " + formatNumber(gap) + " m from cell '" + cell.name +
                                "' that it joins (expected its footprint within " + formatNumber(kMaxWallCellGap) +
                                " m of the cell's region)");
        }
    }

    // A wall's front faces its first cell (cells[0]): the side lowerLeft->lowerRight x
    // lowerLeft->upperLeft points to. Judged by the cells' centroids; a wall whose two cells lie
    // on one side is left to the other checks.
    void checkFacing(std::size_t i) const {
        const VirtualWall& w = d.walls[i];
        const glm::dvec3 n = glm::normalize(glm::cross(w.lowerRight - w.lowerLeft, w.upperLeft - w.lowerLeft));
        double side[2];
        for (int k = 0; k < 2; ++k) {
            glm::dvec2 centroid(0.0);
            for (const glm::dvec2& p : d.cells[w.cells[k]].region) centroid += p;
            centroid /= static_cast<double>(d.cells[w.cells[k]].region.size());
            side[k] = n.x * (centroid.x - w.lowerLeft.x) + n.z * (centroid.y - w.lowerLeft.z);
        }
        if (side[0] < 0.0 && side[1] > 0.0)
            fail("walls[" + std::to_string(i) + "]",
                 "'" + w.name + "' faces its second cell '" + d.cells[w.cells[1]].name +
                     "' (expected its front, lowerLeft->lowerRight x lowerLeft->upperLeft, pointing to " +
                     fmt(glm::dvec3(n.x, 0.0, n.z)) + ", to face its first cell '" + d.cells[w.cells[0]].name +
                     "'); swap the two cells, or lowerLeft with lowerRight (and upperLeft to the new lowerLeft)");
    }

    // Every coordinate the planner and the renderer work with is bounded (absurd extents
    // would make the planner's work and float precision meaningless).
    void checkExtent(const std::string& where, glm::dvec3 p) const {
        for (int a = 0; a < 3; ++a)
            if (!(std::abs(p[a]) <= kMaxSceneCoordinate))
                fail(where, "point " + fmt(p) + " is out of range (expected coordinates within " +
                                formatNumber(kMaxSceneCoordinate) + " m of the origin)");
    }

    void checkExtents() const {
        for (std::size_t i = 0; i < d.models.size(); ++i)
            checkExtent("models[" + std::to_string(i) + "]", glm::dvec3(d.models[i].worldFromFile[3]));
        for (std::size_t i = 0; i < d.cells.size(); ++i)
            for (std::size_t k = 0; k < d.cells[i].region.size(); ++k)
                checkExtent("cells[" + std::to_string(i) + "].region[" + std::to_string(k) + "]",
                            {d.cells[i].region[k].x, d.cells[i].floorY, d.cells[i].region[k].y});
        for (std::size_t i = 0; i < d.walls.size(); ++i)
            for (const glm::dvec3& p : {d.walls[i].lowerLeft, d.walls[i].lowerRight, d.walls[i].upperLeft})
                checkExtent("walls[" + std::to_string(i) + "]", p);
        for (std::size_t i = 0; i < d.realWalls.size(); ++i)
            for (const glm::dvec3& p : {d.realWalls[i].lowerLeft, d.realWalls[i].lowerRight, d.realWalls[i].upperLeft})
                checkExtent("realWalls[" + std::to_string(i) + "]", p);
    }

    void checkModels() const {
        for (std::size_t i = 0; i < d.models.size(); ++i) {
            const std::filesystem::path file =
                d.models[i].file.is_absolute() ? d.models[i].file : d.folder / d.models[i].file;
            std::error_code ec;
            if (!std::filesystem::is_regular_file(file, ec))
                fail("models[" + std::to_string(i) + "].file",
                     "'" + d.models[i].file.string() + "' does not exist (expected a glTF/GLB file, looked for " +
                         file.string() + ")");
            if (std::abs(glm::determinant(d.models[i].worldFromFile)) < 1e-12)
                fail("models[" + std::to_string(i) + "]",
                     "placement matrix is singular (expected a non-zero determinant)");
        }
    }
};

}  // namespace

void validateSceneDescription(const SceneDescription& d, const std::string& source) {
    const Checker c{d, source};
    if (d.models.empty()) c.fail("models", "expected at least one model, got none");
    c.checkModels();
    c.checkExtents();
    for (std::size_t i = 0; i < d.cells.size(); ++i) {
        for (std::size_t j = 0; j < i; ++j)
            if (d.cells[j].name == d.cells[i].name)
                c.fail("cells[" + std::to_string(i) + "].name",
                       "duplicate cell name '" + d.cells[i].name + "' (expected unique names)");
        c.checkCell(i);
    }
    for (std::size_t i = 0; i < d.walls.size(); ++i) {
        c.checkWall(i);
        c.checkFacing(i);
    }
    for (std::size_t i = 0; i < d.realWalls.size(); ++i)
        c.checkQuad("realWalls[" + std::to_string(i) + "]", d.realWalls[i].lowerLeft, d.realWalls[i].lowerRight,
                    d.realWalls[i].upperLeft);
    if (!(d.eyeHeight > 0.0))
        c.fail("viewer.eyeHeight", "expected a positive height, got " + formatNumber(d.eyeHeight));
    if (!(d.headHeightRange.x < d.headHeightRange.y)) c.fail("viewer.headHeightRange", "expected low < high");
    if (!(d.planning.minZone == 0.0 || (d.planning.minZone >= 0.01 && d.planning.minZone <= 1000.0)))
        c.fail("planning.minZone",
               "expected a zone size in [0.01, 1000] metres, got " + formatNumber(d.planning.minZone));
    if (!(d.planning.maxRes == 0 || (d.planning.maxRes >= 16 && d.planning.maxRes <= 16384)))
        c.fail("planning.maxRes",
               "expected a texture side in [16, 16384] texels, got " + std::to_string(d.planning.maxRes));
    for (std::size_t i = 0; i < d.walkBreaks.size(); ++i) {
        const int at = d.walkBreaks[i], after = i > 0 ? d.walkBreaks[i - 1] : 0;
        if (at <= after || at >= static_cast<int>(d.walkPath.size()))
            c.fail("walkBreaks[" + std::to_string(i) + "]",
                   "expected an index of walkPath above " + std::to_string(after) + " and below " +
                       std::to_string(d.walkPath.size()) + ", got " + std::to_string(at));
    }
    if (d.cells.empty()) return;
    for (const auto& [name, path] : {std::pair{"walkPath", &d.walkPath}, std::pair{"wallPath", &d.wallPath}})
        for (std::size_t i = 0; i < path->size(); ++i)
            if (findCell(d.cells, (*path)[i]) < 0)
                c.fail(std::string(name) + "[" + std::to_string(i) + "]",
                       "point " + fmt((*path)[i]) + " is outside every cell (expected a point inside a cell's region)");
}

}  // namespace cavewall::scenes
