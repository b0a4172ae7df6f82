#include "walls/plan.h"

#include "config/error.h"
#include "config/json_reader.h"
#include "scenes/region.h"
#include "walls/angular_error.h"
#include "walls/parallel_for.h"
#include "walls/zone_layout.h"

#include <algorithm>
#include <cmath>

namespace cavewall::walls {
namespace {

using config::formatNumber;

void require(bool ok, const std::string& what) {
    if (!ok) throw Error("plan options: " + what);
}

SideFrame frameOf(const scenes::VirtualWall& wall, int side) {
    const display::ScreenBasis b = display::screenBasis({wall.lowerLeft, wall.lowerRight, wall.upperLeft});
    const glm::dvec2 n(b.normal.x, b.normal.z);
    // A wall tilted by more than 60° has no useful floor frame.
    if (glm::length(n) < 0.5)
        throw Error("wall '" + wall.name +
                    "': cannot plan zones for a wall that is not upright (expected a tilt below 60°, got a normal of " +
                    formatNumber(b.normal.x) + ", " + formatNumber(b.normal.y) + ", " + formatNumber(b.normal.z) + ")");
    SideFrame f;
    f.origin = {wall.lowerLeft.x, wall.lowerLeft.z};
    f.inward = glm::normalize(n) * (side == 0 ? 1.0 : -1.0);
    f.along = {-f.inward.y, f.inward.x};
    return f;
}

// The planner's work grows with a cell's size in zones; absurd sizes are refused up front.
void checkExtent(const scenes::Cell& cell) {
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi = -lo;
    for (const glm::dvec2& p : cell.region) {
        lo = glm::min(lo, p);
        hi = glm::max(hi, p);
    }
    const double extent = std::max(hi.x - lo.x, hi.y - lo.y);
    if (!(extent <= kMaxCellExtent))
        throw Error("cell '" + cell.name + "': extent of " + formatNumber(extent) +
                    " m is too large to plan (expected at most " + formatNumber(kMaxCellExtent) + " m)");
}

}  // namespace

const char* toString(ZoneKind kind) {
    switch (kind) {
        case ZoneKind::Texture: return "texture";
        case ZoneKind::Blend: return "blend";
        case ZoneKind::Geometry: return "geometry";
    }
    return "?";
}

void useScenePlanning(const scenes::SceneDescription& description, PlanningFlags given, PlanOptions& plan,
                      int& maxResolution) {
    const scenes::SceneDescription::Planning& own = description.planning;
    if (!given.minZone && own.minZone > 0.0) {
        if (!(own.minZone > 2 * plan.blendWidth))
            throw Error("scene '" + description.name + "': planning.minZone: expected more than twice the blend " +
                        "width (" + formatNumber(2 * plan.blendWidth) + " m), got " + formatNumber(own.minZone) +
                        " m (or give --min-zone)");
        plan.minZoneSize = own.minZone;
    }
    if (!given.maxRes && own.maxRes > 0) maxResolution = own.maxRes;
}

void validatePlanOptions(const PlanOptions& o) {
    require(o.alphaDeg > 0 && o.alphaDeg <= 90,
            "alpha: expected an angle in (0, 90] degrees, got " + formatNumber(o.alphaDeg));
    require(o.blendWidth >= 0 && std::isfinite(o.blendWidth),
            "blendWidth: expected a finite width >= 0 m, got " + formatNumber(o.blendWidth));
    require(o.minZoneSize > 2 * o.blendWidth && std::isfinite(o.minZoneSize),
            "minZoneSize: expected more than twice blendWidth (" + formatNumber(2 * o.blendWidth) + " m), got " +
                formatNumber(o.minZoneSize) + " m");
    require(o.pixelsPerDegree > 0 && o.pixelsPerDegree <= 1000,
            "pixelsPerDegree: expected a number in (0, 1000], got " + formatNumber(o.pixelsPerDegree));
    require(o.maxResolution >= 1 && o.maxResolution <= 16384,
            "maxResolution: expected an integer in [1, 16384], got " + std::to_string(o.maxResolution));
}

double texelSize(double distance, double pixelsPerDegree) {
    return distance * std::tan(glm::radians(1.0 / pixelsPerDegree));
}

double nearestDistance(const Polygon2& region, double y, const ScreenQuad& q) {
    const glm::dvec3 n = display::screenBasis(q).normal;
    double d = std::numeric_limits<double>::infinity();
    for (const glm::dvec2& p : region) d = std::min(d, std::abs(glm::dot(glm::dvec3(p.x, y, p.y) - q.lowerLeft, n)));
    return d;
}

glm::ivec2 capResolution(glm::dvec2 texels, int maxResolution) {
    texels = glm::max(texels, glm::dvec2(1.0));
    const double largest = std::max(texels.x, texels.y);
    if (largest <= maxResolution) return glm::ivec2(texels);
    return glm::max(glm::ivec2(glm::round(texels * (double(maxResolution) / largest))), glm::ivec2(1));
}

glm::ivec2 bakeResolution(glm::ivec2 planned, int maxResolution, WallKind kind) {
    glm::ivec2 r = capResolution(glm::dvec2(planned), maxResolution);
    if (kind == WallKind::Depth)
        for (int axis = 0; axis < 2; ++axis)
            if (r[axis] % 2 != 0) r[axis] += r[axis] + 1 <= maxResolution ? 1 : -1;
    return r;
}

glm::ivec2 textureResolution(double nearest, const display::ScreenQuad& q, const PlanOptions& options) {
    const display::ScreenBasis b = display::screenBasis(q);
    double texel = texelSize(nearest, options.pixelsPerDegree);
    if (!(texel > 1e-9)) texel = 1e-9;  // an eye on the plane: the cap on the longer side
    return capResolution({std::ceil(b.width / texel), std::ceil(b.height / texel)}, options.maxResolution);
}

double texelDiagonal(const display::ScreenQuad& q, glm::ivec2 resolution) {
    const display::ScreenBasis b = display::screenBasis(q);
    return std::hypot(b.width / std::max(1, resolution.x), b.height / std::max(1, resolution.y));
}

double depthTextureBound(const ZoneVolume& volume, glm::dvec3 samplingPoint, const ScreenQuad& wall, glm::dvec2 span,
                         const PlanOptions& options) {
    const glm::ivec2 resolution =
        textureResolution(nearestDistance(volume.floor, samplingPoint.y, wall), wall, options);
    const double h = texelDiagonal(wall, resolution);
    return std::min(depthZoneBound(volume, samplingPoint, wall, span, h),
                    depthSegmentZoneBound(volume, samplingPoint, wall, span, h));
}

bool depthTextureWithin(const ZoneVolume& volume, glm::dvec3 samplingPoint, const ScreenQuad& wall, glm::dvec2 span,
                        const PlanOptions& options, double alpha) {
    const glm::ivec2 resolution =
        textureResolution(nearestDistance(volume.floor, samplingPoint.y, wall), wall, options);
    const double h = texelDiagonal(wall, resolution);
    return depthSegmentZoneWithin(volume, samplingPoint, wall, span, h, alpha) ||
           depthZoneWithin(volume, samplingPoint, wall, span, h, alpha);
}

double textureErrorAt(const Plan& plan, const Texture& t, glm::dvec3 eye) {
    const PlannedWall& w = plan.walls[t.wall];
    if (plan.options.wallKind == WallKind::Flat) return maxAngularError(eye, t.samplingPoint, w.quad, w.depthBehind);
    const double h = texelDiagonal(w.quad, t.resolution);
    const glm::dvec2 span(w.depthNear, w.depthBehind);
    return std::min(depthEyeBound(eye, t.samplingPoint, w.quad, span, h),
                    depthSegmentEyeBound(eye, t.samplingPoint, w.quad, span, h));
}

Plan planZones(const scenes::SceneDescription& d, const PlanOptions& options, const std::vector<glm::dvec2>& spans) {
    validatePlanOptions(options);
    if (!spans.empty() && spans.size() != d.walls.size())
        throw Error("plan: expected a depth span per wall (" + std::to_string(d.walls.size()) + "), got " +
                    std::to_string(spans.size()));
    Plan plan;
    plan.alphaDeg = options.alphaDeg;
    plan.options = options;
    std::vector<SideInput> inputs;
    for (int w = 0; w < int(d.walls.size()); ++w) {
        const scenes::VirtualWall& wall = d.walls[w];
        const glm::dvec2 span = spans.empty() ? glm::dvec2(0.0, std::numeric_limits<double>::infinity()) : spans[w];
        if (!(span.x >= 0.0 && span.y >= span.x))
            throw Error("wall '" + wall.name + "': expected a depth span 0 <= near <= far, got " +
                        formatNumber(span.x) + " .. " + formatNumber(span.y) + " m");
        plan.walls.push_back(
            {w, wall.name, {wall.lowerLeft, wall.lowerRight, wall.upperLeft}, wall.cells, span.y, span.x});
        for (int side = 0; side < 2; ++side) {
            const int cell = wall.cells[side];
            if (cell < 0 || cell >= int(d.cells.size())) continue;
            checkExtent(d.cells[cell]);
            inputs.push_back({cell, w, side, frameOf(wall, side), d.cells[cell].region, plan.walls.back().quad,
                              scenes::cellHeadHeights(d, cell)});
        }
    }
    plan.sides = planSides(plan, inputs, plan.zones);
    planBeyond(plan, d);
    parallelFor(int(plan.textures.size()), [&](int i) {
        Texture& t = plan.textures[i];
        const PlannedWall& w = plan.walls[t.wall];
        const ZoneVolume volume{t.validRegion, scenes::cellHeadHeights(d, t.cell)};
        t.resolution = textureResolution(nearestDistance(t.validRegion, t.samplingPoint.y, w.quad), w.quad, options);
        t.maxError = options.wallKind == WallKind::Flat
                         ? zoneMaxError(volume, t.samplingPoint, w.quad)
                         : depthTextureBound(volume, t.samplingPoint, w.quad, {w.depthNear, w.depthBehind}, options);
    });
    return plan;
}

int findZone(const Plan& plan, int cell, int wall, glm::dvec2 p) {
    for (const WallSide& s : plan.sides) {
        if (s.cell != cell || s.wall != wall) continue;
        for (int z = s.firstZone; z < s.firstZone + s.zoneCount; ++z)
            if (containsConvex(plan.zones[z].floorPolygon, p)) return z;
    }
    return -1;
}

display::ScreenQuad quadSeenFrom(const display::ScreenQuad& wall, int side) {
    if (side == 0) return wall;
    const glm::dvec3 up = wall.upperLeft - wall.lowerLeft;
    return {wall.lowerRight, wall.lowerLeft, wall.lowerRight + up};
}

}  // namespace cavewall::walls
