#include "walls/plan_io.h"

#include "config/json_reader.h"
#include "walls/depth_wall.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <set>

namespace cavewall::walls {
namespace {

nlohmann::json vec(glm::dvec3 v) { return {v.x, v.y, v.z}; }

ZoneKind kindFrom(const std::string& s) {
    return s == "texture" ? ZoneKind::Texture : s == "blend" ? ZoneKind::Blend : ZoneKind::Geometry;
}

PlannedWall wallFrom(const config::JsonNode& n, int index) {
    n.expectKeys({"id", "lowerLeft", "lowerRight", "upperLeft", "cells", "depthBehind", "depthNear"});
    PlannedWall w;
    w.id = n.at("id").integer(index, index);
    w.quad = {n.at("lowerLeft").vec3(), n.at("lowerRight").vec3(), n.at("upperLeft").vec3()};
    const auto cells = n.at("cells").items(2, 2);
    w.cells = {cells[0].integer(-1, 1 << 30), cells[1].integer(-1, 1 << 30)};
    const config::JsonNode depth = n.at("depthBehind");
    w.depthBehind = depth.raw().is_null() ? std::numeric_limits<double>::infinity() : depth.number(0, 1e12);
    if (n.has("depthNear")) w.depthNear = n.at("depthNear").number(0, w.depthBehind);
    return w;
}

glm::dvec3 pointFrom(const config::JsonNode& n) { return n.vec3(); }

using TextureIds = std::map<std::tuple<int, int, double, double, double>, int>;

int textureFor(Plan& plan, TextureIds& ids, const Zone& z, glm::dvec3 s) {
    const auto key = std::make_tuple(z.cell, z.wall, s.x, s.y, s.z);
    if (auto it = ids.find(key); it != ids.end()) return it->second;
    Texture t;
    t.id = int(plan.textures.size());
    t.cell = z.cell;
    t.wall = z.wall;
    t.samplingPoint = s;
    plan.textures.push_back(t);
    return ids[key] = t.id;
}

// A zone object without its key check (the caller knows which keys its list allows).
Zone zoneFrom(const config::JsonNode& n, int index, Plan& plan, TextureIds& ids) {
    Zone z;
    z.id = n.at("id").integer(index, index);
    z.cell = n.at("cell").integer(0, 1 << 30);
    z.wall = n.at("wall").integer(0, int(plan.walls.size()) - 1);
    z.kind = kindFrom(n.at("kind").oneOf({"texture", "blend", "geometry"}));
    for (const auto& p : n.at("floorPolygon").items(3)) z.floorPolygon.push_back(p.vec2());
    z.heightRange = n.at("heightRange").vec2();
    if (z.kind == ZoneKind::Texture) z.textures.push_back(textureFor(plan, ids, z, pointFrom(n.at("samplingPoint"))));
    if (z.kind == ZoneKind::Blend) {
        for (const auto& p : n.at("samplingPoints").items(1))
            z.textures.push_back(textureFor(plan, ids, z, pointFrom(p)));
        z.mixesGeometry = n.at("mixesGeometry").boolean();
    }
    return z;
}

// Consecutive beyond zones of one eye region and far wall form one BeyondSide (as written); its
// eye region and parent are not stored (the zones tile the region).
void readBeyond(const std::vector<config::JsonNode>& zones, Plan& plan, TextureIds& ids) {
    for (int i = 0; i < int(zones.size()); ++i) {
        const config::JsonNode& n = zones[i];
        n.expectKeys({"id", "cell", "wall", "kind", "floorPolygon", "heightRange", "samplingPoint", "samplingPoints",
                      "mixesGeometry", "eyeCell", "viaWall"});
        Zone z = zoneFrom(n, i, plan, ids);
        const int eyeCell = n.at("eyeCell").integer(0, 1 << 30);
        const int via = n.at("viaWall").integer(-1, int(plan.walls.size()) - 1);
        const bool same = !plan.beyond.empty() && plan.beyond.back().eyeCell == eyeCell &&
                          plan.beyond.back().viaWall == via && plan.beyond.back().side.cell == z.cell &&
                          plan.beyond.back().side.wall == z.wall;
        if (!same) {
            BeyondSide b{eyeCell, via, {}, {}};
            b.side.cell = z.cell;
            b.side.wall = z.wall;
            b.side.firstZone = i;
            b.side.side = plan.walls[z.wall].cells[0] == z.cell ? 0 : 1;
            plan.beyond.push_back(b);
        }
        plan.beyond.back().side.zoneCount++;
        plan.beyondZones.push_back(std::move(z));
    }
}

nlohmann::json zoneToJson(const Plan& plan, const Zone& z) {
    nlohmann::json polygon = nlohmann::json::array();
    for (const glm::dvec2& p : z.floorPolygon) polygon.push_back({p.x, p.y});
    nlohmann::json j = {{"id", z.id},
                        {"cell", z.cell},
                        {"wall", z.wall},
                        {"kind", toString(z.kind)},
                        {"floorPolygon", polygon},
                        {"heightRange", {z.heightRange.x, z.heightRange.y}}};
    if (z.kind == ZoneKind::Texture) j["samplingPoint"] = vec(plan.textures[z.textures.at(0)].samplingPoint);
    if (z.kind == ZoneKind::Blend) {
        nlohmann::json points = nlohmann::json::array();
        for (int t : z.textures) points.push_back(vec(plan.textures[t].samplingPoint));
        j["samplingPoints"] = points;
        j["mixesGeometry"] = z.mixesGeometry;
    }
    return j;
}

int eyeRegionCount(const Plan& plan) {
    std::set<std::pair<int, int>> regions;
    for (const BeyondSide& b : plan.beyond) regions.insert({b.eyeCell, b.viaWall});
    return int(regions.size());
}

}  // namespace

nlohmann::json planToJson(const Plan& plan) {
    nlohmann::json walls = nlohmann::json::array(), zones = nlohmann::json::array();
    for (const PlannedWall& w : plan.walls)
        walls.push_back(
            {{"id", w.id},
             {"lowerLeft", vec(w.quad.lowerLeft)},
             {"lowerRight", vec(w.quad.lowerRight)},
             {"upperLeft", vec(w.quad.upperLeft)},
             {"cells", {w.cells[0], w.cells[1]}},
             {"depthBehind", std::isfinite(w.depthBehind) ? nlohmann::json(w.depthBehind) : nlohmann::json()},
             {"depthNear", w.depthNear}});
    for (const Zone& z : plan.zones) zones.push_back(zoneToJson(plan, z));
    nlohmann::json beyond = nlohmann::json::array();
    for (const BeyondSide& b : plan.beyond)
        for (int z = b.side.firstZone; z < b.side.firstZone + b.side.zoneCount; ++z) {
            nlohmann::json j = zoneToJson(plan, plan.beyondZones[z]);
            j["eyeCell"] = b.eyeCell;
            j["viaWall"] = b.viaWall;
            beyond.push_back(j);
        }
    nlohmann::json textures = nlohmann::json::array();
    for (const Texture& t : plan.textures)
        textures.push_back({{"id", t.id},
                            {"cell", t.cell},
                            {"wall", t.wall},
                            {"samplingPoint", vec(t.samplingPoint)},
                            {"resolution", {t.resolution.x, t.resolution.y}},
                            {"maxError", t.maxError}});
    return {{"alphaDeg", plan.alphaDeg},
            {"wallKind", std::string(wallKindName(plan.options.wallKind))},
            {"walls", walls},
            {"zones", zones},
            {"beyondZones", beyond},
            {"textures", textures}};
}

Plan planFromJson(std::string_view text, const std::string& source) {
    const config::JsonDocument doc = config::JsonDocument::fromText(text, source);
    const config::JsonNode root = doc.root();
    root.expectKeys({"alphaDeg", "wallKind", "walls", "zones", "beyondZones", "textures"});
    Plan plan;
    plan.alphaDeg = root.at("alphaDeg").number(1e-9, 90);
    plan.options.alphaDeg = plan.alphaDeg;
    if (root.has("wallKind"))
        plan.options.wallKind =
            root.at("wallKind").oneOf({"flat", "depth"}) == "depth" ? WallKind::Depth : WallKind::Flat;
    const auto walls = root.at("walls").items();
    for (int i = 0; i < int(walls.size()); ++i) plan.walls.push_back(wallFrom(walls[i], i));
    TextureIds ids;
    // The texture list first when present, so that ids, resolutions and bounds survive.
    if (root.has("textures")) {
        const auto textures = root.at("textures").items();
        for (int i = 0; i < int(textures.size()); ++i) {
            const config::JsonNode& n = textures[i];
            n.expectKeys({"id", "cell", "wall", "samplingPoint", "resolution", "maxError"});
            Texture t;
            t.id = n.at("id").integer(i, i);
            t.cell = n.at("cell").integer(0, 1 << 30);
            t.wall = n.at("wall").integer(0, int(plan.walls.size()) - 1);
            t.samplingPoint = pointFrom(n.at("samplingPoint"));
            const auto r = n.at("resolution").items(2, 2);
            t.resolution = {r[0].integer(0, 1 << 20), r[1].integer(0, 1 << 20)};
            t.maxError = n.at("maxError").number(0, 4);
            ids[std::make_tuple(t.cell, t.wall, t.samplingPoint.x, t.samplingPoint.y, t.samplingPoint.z)] = t.id;
            plan.textures.push_back(t);
        }
    }
    const auto zones = root.at("zones").items();
    for (int i = 0; i < int(zones.size()); ++i) {
        zones[i].expectKeys({"id", "cell", "wall", "kind", "floorPolygon", "heightRange", "samplingPoint",
                             "samplingPoints", "mixesGeometry"});
        plan.zones.push_back(zoneFrom(zones[i], i, plan, ids));
    }
    if (root.has("beyondZones")) readBeyond(root.at("beyondZones").items(), plan, ids);
    return plan;
}

PlanTotals planTotals(const Plan& plan) {
    PlanTotals t;
    for (const Zone& z : plan.zones)
        (z.kind == ZoneKind::Texture ? t.textureZones : z.kind == ZoneKind::Blend ? t.blendZones : t.geometryZones)++;
    t.textures = int(plan.textures.size());
    t.beyondZones = int(plan.beyondZones.size());
    for (const BeyondSide& b : plan.beyond) t.beyondTextures += b.side.textureCount;
    // Depth walls add the halved depths the march reads (marchDepthSize of the baked size,
    // bakeResolution, whose sides are even; the bake writes them so): depthTextureBytes on the
    // GPU and a 16-bit code per depth texel on disk (walls/depth_file.h).
    const bool depth = plan.options.wallKind == WallKind::Depth;
    double depthGpuBytes = 0.0, depthDiskBytes = 0.0;
    for (const Texture& tex : plan.textures) {
        t.texels += double(tex.resolution.x) * tex.resolution.y;
        if (depth) {
            const glm::ivec2 baked = bakeResolution(tex.resolution, plan.options.maxResolution, WallKind::Depth);
            const glm::ivec2 march = marchDepthSize(baked.x, baked.y);
            depthGpuBytes += double(depthTextureBytes(march.x, march.y));
            depthDiskBytes += 2.0 * march.x * march.y;
        }
        t.maxErrorDeg = std::max(t.maxErrorDeg, glm::degrees(tex.maxError));
    }
    t.gpuBytes = t.texels * 4.0 * 4.0 / 3.0 + depthGpuBytes;
    t.diskBytes = t.texels * 4.0 * 4.0 / 3.0 + depthDiskBytes;
    return t;
}

void printPlanSummary(std::ostream& out, const Plan& plan, const scenes::SceneDescription& d) {
    const PlanTotals totals = planTotals(plan);
    char line[256];
    std::snprintf(line, sizeof line, "plan '%s': alpha %g°, %zu cells, %zu walls, head heights %g-%g m\n",
                  d.name.c_str(), plan.alphaDeg, d.cells.size(), plan.walls.size(), d.headHeightRange.x,
                  d.headHeightRange.y);
    out << line;
    std::snprintf(line, sizeof line, "%-16s %-16s %10s %9s %9s %9s %9s %10s\n", "cell", "wall", "geometry", "texture",
                  "blend", "geom", "textures", "Mtexels");
    out << line;
    for (const WallSide& s : plan.sides) {
        int kinds[3] = {0, 0, 0};
        double texels = 0;
        for (int z = s.firstZone; z < s.firstZone + s.zoneCount; ++z) kinds[int(plan.zones[z].kind)]++;
        for (const Texture& t : plan.textures)
            if (t.cell == s.cell && t.wall == s.wall) texels += double(t.resolution.x) * t.resolution.y;
        std::snprintf(line, sizeof line, "%-16s %-16s %8.2f m %9d %9d %9d %9d %10.2f\n", d.cells[s.cell].name.c_str(),
                      plan.walls[s.wall].name.c_str(), s.geometryDistance, kinds[0], kinds[1], kinds[2], s.textureCount,
                      texels * 1e-6);
        out << line;
    }
    std::snprintf(line, sizeof line,
                  "beyond a neighbour drawn as geometry: %zu far walls from %d eye regions, %d zones, %d textures\n",
                  plan.beyond.size(), eyeRegionCount(plan), totals.beyondZones, totals.beyondTextures);
    out << line;
    const bool depth = plan.options.wallKind == WallKind::Depth;
    std::snprintf(
        line, sizeof line,
        "total: %d texture, %d blend, %d geometry zones; %d textures, %.2f Mtexels; GPU %.1f MiB (RGBA8 + MIP "
        "chain%s); disk <= %.1f MiB (uncompressed tiled + MIP%s)\n",
        totals.textureZones, totals.blendZones, totals.geometryZones, totals.textures, totals.texels * 1e-6,
        totals.gpuBytes / 1048576.0, depth ? " + R32F depth" : "", totals.diskBytes / 1048576.0,
        depth ? " + 16-bit depth" : "");
    out << line;
    std::snprintf(line, sizeof line, "%s walls: largest texture error bound %.3f° (alpha %g°; %s)\n",
                  depth ? "depth" : "flat", totals.maxErrorDeg, plan.alphaDeg,
                  depth ? "depth reprojection bound, span or segment form, walls/depth_wall.h"
                        : "flat bound at any depth, walls/angular_error.h");
    out << line;
    std::snprintf(
        line, sizeof line,
        "texel density: %g px/degree at the nearest point of each texture's valid region, capped at %d texels "
        "per side\n",
        plan.options.pixelsPerDegree, plan.options.maxResolution);
    out << line;
}

}  // namespace cavewall::walls
