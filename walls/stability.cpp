#include "walls/stability.h"

#include "config/json_reader.h"
#include "walls/angular_error.h"
#include "walls/frame_select.h"
#include "walls/polygon2d.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace cavewall::walls {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::map<int, double> weights(const WallBlend& w) {
    std::map<int, double> m(w.textures.begin(), w.textures.end());
    m[-1] = w.geometryWeight;
    return m;
}

struct BorderFigures {
    double sumError = 0.0, jump = 0.0;
    int outside = 0;
};

// Weights at p and 1 nm either side of the edge with direction `along`.
void probe(const FrameSelector& selector, const Plan& plan, glm::dvec2 p, glm::dvec2 along, BorderFigures& f) {
    const WallBlend at = selector.blendAt(0, p);
    double sum = at.geometryWeight;
    for (const auto& [id, w] : at.textures) {
        sum += w;
        f.outside += !containsConvex(plan.textures[id].validRegion, p, 1e-9);
    }
    f.sumError = std::max(f.sumError, std::abs(sum - 1.0));
    const glm::dvec2 n = glm::normalize(glm::dvec2(-along.y, along.x)) * 1e-9;
    const auto here = weights(at);
    for (glm::dvec2 q : {p + n, p - n}) {
        for (const auto& [id, w] : weights(selector.blendAt(0, q))) {
            const auto it = here.find(id);
            f.jump = std::max(f.jump, std::abs(w - (it == here.end() ? 0.0 : it->second)));
        }
    }
}

}  // namespace

scenes::SceneDescription referenceHall() {
    scenes::SceneDescription d;
    d.name = "reference hall";
    d.cells.push_back({"front", {{6, 0}, {6, 10}, {-6, 10}, {-6, 0}}, 0.0});
    d.cells.push_back({"back", {{6, -10}, {6, 0}, {-6, 0}, {-6, -10}}, 0.0});
    scenes::VirtualWall w;
    w.name = "middle";
    w.lowerLeft = {-6, 0, 0};
    w.lowerRight = {6, 0, 0};
    w.upperLeft = {-6, 3, 0};
    w.cells = {0, 1};
    d.walls.push_back(w);
    d.headHeightRange = {1.2, 2.0};
    return d;
}

std::vector<display::StabilityRow> blendBorderCases() {
    const scenes::SceneDescription d = referenceHall();
    const Plan plan = planZones(d, PlanOptions{});
    const VisibilityTable table = computeVisibility(d);
    const FrameSelector selector(plan, table, d);
    BorderFigures f;
    const WallSide& side = plan.sides[0];
    for (int z = side.firstZone; z < side.firstZone + side.zoneCount; ++z) {
        const Polygon2& poly = plan.zones[z].floorPolygon;
        for (std::size_t i = 0; i < poly.size(); ++i) {
            const glm::dvec2 a = poly[i], b = poly[(i + 1) % poly.size()];
            if (glm::distance(a, b) < 1e-12) continue;
            probe(selector, plan, a, b - a, f);
            probe(selector, plan, 0.5 * (a + b), b - a, f);
        }
    }
    const std::string n = " (" + std::to_string(side.zoneCount) + " zones, alpha 10°)";
    return {{"blend weights on zone borders: abs(sum - 1)" + n, "weight", kNaN, f.sumError, 1e-12},
            {"blend weights across zone borders (1 nm): jump" + n, "weight", kNaN, f.jump, 1e-6},
            {"blend weights on zone borders: outside proven region" + n, "weights", kNaN, double(f.outside), 0.0}};
}

std::vector<display::StabilityRow> alphaExtremeCases() {
    const scenes::SceneDescription d = referenceHall();
    std::vector<display::StabilityRow> rows;
    for (double alphaDeg : {1e-4, 0.1, 45.0, 89.9, 90.0}) {
        PlanOptions o;
        o.alphaDeg = alphaDeg;
        const Plan plan = planZones(d, o);
        double ratio = 0.0;
        for (const Zone& zone : plan.zones)
            for (int t : zone.textures) {
                const Texture& tex = plan.textures[t];
                const double e =
                    zoneMaxError({zone.floorPolygon, zone.heightRange}, tex.samplingPoint, plan.walls[zone.wall].quad);
                ratio = std::max(ratio, e / glm::radians(alphaDeg));
            }
        rows.push_back({"plan at alpha " + config::formatNumber(alphaDeg) + "° (" +
                            std::to_string(plan.textures.size()) + " textures): max zone error / alpha",
                        "ratio", kNaN, ratio, 1.0});
    }
    return rows;
}

}  // namespace cavewall::walls
