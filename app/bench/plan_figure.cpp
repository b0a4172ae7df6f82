#include "app/bench/plan_figure.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace cavewall::bench {

namespace {

// The storey whose floor is the highest at or below `y` (half a metre of slack: a wall's foot
// may sit just under its floor's mean height); the lowest when none is.
std::size_t storeyOf(const std::vector<double>& floors, double y) {
    std::size_t storey = 0;
    for (std::size_t i = 0; i < floors.size(); ++i)
        if (floors[i] <= y + 0.5) storey = i;
    return storey;
}

std::vector<PlotPoint> topView(const walls::Polygon2& polygon) {
    std::vector<PlotPoint> out;
    for (const glm::dvec2& p : polygon) out.push_back({p.x, p.y});
    return out;
}

std::vector<PlotPoint> footprint(const glm::dvec3& a, const glm::dvec3& b) { return {{a.x, a.z}, {b.x, b.z}}; }

std::string metres(double v) {
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.2f", v);
    return buffer;
}

// Series in legend order; each panel lists all of them so that the legend is the same.
enum Layer : std::size_t { kTextureZones, kBlendZones, kGeometryZones, kCells, kRealWalls, kVirtualWalls, kLayers };

std::vector<PlotSeries> emptyLayers() {
    std::vector<PlotSeries> layers(kLayers);
    layers[kTextureZones] = {"texture zone (one texture shown)", {}, SeriesStyle::Filled, {}, "#4daf4a"};
    layers[kBlendZones] = {"blend strip (textures cross-faded)", {}, SeriesStyle::Filled, {}, "#ffd92f"};
    layers[kGeometryZones] = {"geometry zone (cell behind drawn)", {}, SeriesStyle::Filled, {}, "#e41a1c"};
    layers[kCells] = {"cell", {}, SeriesStyle::Outlines, {}, "#303030", 1.5};
    layers[kRealWalls] = {"real wall", {}, SeriesStyle::Paths, {}, "#000000", 3.0};
    layers[kVirtualWalls] = {"virtual wall", {}, SeriesStyle::Paths, {}, "#1f4fd0", 2.5};
    return layers;
}

std::size_t zoneLayer(walls::ZoneKind kind) {
    if (kind == walls::ZoneKind::Texture) return kTextureZones;
    return kind == walls::ZoneKind::Blend ? kBlendZones : kGeometryZones;
}

// Pixels per row of panels: a plot area about 640 pixels wide at the cells' aspect (z extent
// over x extent), plus the title and the x axis; 360 to 1000.
int rowHeight(const scenes::SceneDescription& d) {
    glm::dvec2 lo(INFINITY), hi(-INFINITY);
    for (const scenes::Cell& c : d.cells)
        for (const glm::dvec2& p : c.region) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    const double aspect = hi.x > lo.x ? (hi.y - lo.y) / (hi.x - lo.x) : 1.0;
    return static_cast<int>(std::clamp(640.0 * aspect + 160.0, 360.0, 1000.0));
}

}  // namespace

std::vector<double> storeyFloors(const scenes::SceneDescription& description, double gap) {
    std::vector<double> heights;
    for (const scenes::Cell& c : description.cells) heights.push_back(c.floorY);
    std::sort(heights.begin(), heights.end());
    std::vector<double> floors;
    for (double y : heights)
        if (floors.empty() || y - floors.back() >= gap) floors.push_back(y);
    if (floors.empty()) floors.push_back(0.0);
    return floors;
}

Figure planFigure(const walls::Plan& plan, const scenes::SceneDescription& d, const std::string& title) {
    const std::vector<double> floors = storeyFloors(d);
    std::vector<std::vector<PlotSeries>> layers(floors.size(), emptyLayers());
    std::vector<int> cells(floors.size(), 0), walls(floors.size(), 0);
    const auto cellStorey = [&](int cell) {
        return cell >= 0 && cell < static_cast<int>(d.cells.size()) ? storeyOf(floors, d.cells[cell].floorY) : 0;
    };
    for (std::size_t i = 0; i < d.cells.size(); ++i) {
        layers[cellStorey(static_cast<int>(i))][kCells].shapes.push_back(topView(d.cells[i].region));
        ++cells[cellStorey(static_cast<int>(i))];
    }
    for (const walls::Zone& z : plan.zones)
        layers[cellStorey(z.cell)][zoneLayer(z.kind)].shapes.push_back(topView(z.floorPolygon));
    for (const scenes::RealWall& w : d.realWalls)
        layers[storeyOf(floors, w.lowerLeft.y)][kRealWalls].shapes.push_back(footprint(w.lowerLeft, w.lowerRight));
    for (const scenes::VirtualWall& w : d.walls) {
        const std::size_t storey = w.cells[0] >= 0 ? cellStorey(w.cells[0]) : storeyOf(floors, w.lowerLeft.y);
        layers[storey][kVirtualWalls].shapes.push_back(footprint(w.lowerLeft, w.lowerRight));
        ++walls[storey];
    }
    Figure figure;
    for (std::size_t s = 0; s < floors.size(); ++s) {
        PlotPanel panel;
        panel.title = title + ": storey " + std::to_string(s + 1) + " of " + std::to_string(floors.size()) +
                      ", floor y " + metres(floors[s]) + " m, " + std::to_string(cells[s]) + " cells, " +
                      std::to_string(walls[s]) + " virtual walls";
        panel.x = {"x", "m", false};
        panel.y = {"z (down: looking from above)", "m", false, false, true};
        panel.equalScale = true;
        panel.series = std::move(layers[s]);
        figure.panels.push_back(std::move(panel));
    }
    figure.columns = std::min<int>(2, static_cast<int>(floors.size()));
    const int rows = (static_cast<int>(floors.size()) + figure.columns - 1) / figure.columns;
    figure.legendWidth = 400;
    figure.width = figure.columns * 760 + figure.legendWidth;
    figure.height = rows * rowHeight(d) + 40;
    return figure;
}

}  // namespace cavewall::bench
