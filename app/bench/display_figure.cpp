#include "app/bench/display_figure.h"

#include "config/json_reader.h"
#include "display/display_summary.h"
#include "display/stereo.h"

#include <algorithm>
#include <cmath>

namespace cavewall::bench {

namespace {

// Okabe & Ito (2008) colours without red (the overlap's) and black (shared edges, normals).
constexpr const char* kScreenColours[] = {"#0072b2", "#009e73", "#e69f00", "#cc79a7", "#56b4e9", "#999933", "#d55e00"};

// One panel's projection: which cave axes become the panel's x and y.
struct Projection {
    std::string name;
    PlotAxis x, y;
    glm::dvec2 (*project)(const glm::dvec3&);
};

glm::dvec2 fromAbove(const glm::dvec3& p) { return {p.x, p.z}; }
glm::dvec2 fromFront(const glm::dvec3& p) { return {p.x, p.y}; }

PlotPoint point(glm::dvec2 p) { return {p.x, p.y}; }

// Everything both panels draw, in the cave frame.
struct Content {
    std::vector<display::ScreenFacts> screens;
    std::vector<display::SharedEdge> edges;
    std::vector<display::ScreenOverlap> overlaps;
    glm::dvec3 head{0.0}, viewDirection{0.0, 0.0, -1.0};
    std::vector<std::pair<std::string, glm::dvec3>> eyes;  // stereo only
    std::optional<std::array<glm::dvec3, 2>> volume;
    double arrowLength = 0.3;  // metres: the normals' and the view direction's arrows
};

Content contentOf(const config::DisplayConfig& c) {
    Content out;
    out.screens = display::screenFacts(c);
    out.edges = display::sharedEdges(out.screens);
    out.overlaps = display::screenOverlaps(out.screens);
    out.head = c.viewer.headPosition;
    out.viewDirection = c.viewer.headOrientation * glm::dvec3(0.0, 0.0, -1.0);
    if (c.stereo != config::StereoMode::Mono) {
        const std::string apart = " (eyes " + config::formatNumber(c.viewer.eyeSeparation * 1000.0) + " mm apart)";
        for (display::Eye eye : {display::Eye::Left, display::Eye::Right})
            out.eyes.push_back({std::string(display::toString(eye)) + " eye" + apart,
                                display::eyePosition(out.head, c.viewer.headOrientation, c.viewer.eyeSeparation, eye)});
    }
    out.volume = c.tracking.volume;
    // A sixth of the largest screen edge, so that arrows read at the screens' scale.
    double largest = 0.0;
    for (const display::ScreenFacts& s : out.screens) largest = std::max({largest, s.basis.width, s.basis.height});
    out.arrowLength = std::clamp(largest / 6.0, 0.05, 2.0);
    return out;
}

double projectedArea(const std::vector<glm::dvec2>& poly) {
    double twice = 0.0;
    for (std::size_t i = 0; i < poly.size(); ++i)
        twice += poly[i].x * poly[(i + 1) % poly.size()].y - poly[(i + 1) % poly.size()].x * poly[i].y;
    return std::abs(twice) / 2.0;
}

// Where a screen's name goes: its centre, under the head's marker when that is on the centre;
// for a screen seen edge-on, at the tip of its normal's arrow, on the far side of the tip.
PlotLabel labelOf(const display::ScreenFacts& s, const Content& content, const Projection& view) {
    std::vector<glm::dvec2> poly;
    for (const glm::dvec3& p : display::outline(s)) poly.push_back(view.project(p));
    const glm::dvec2 centre = view.project(s.centre);
    const glm::dvec2 normal = view.project(s.basis.normal);
    if (projectedArea(poly) < 0.1 * s.basis.width * s.basis.height && glm::length(normal) > 0.05) {
        const glm::dvec2 tip = centre + normal * content.arrowLength;
        // The arrow's direction on the page, where a reversed axis points the other way.
        const glm::dvec2 page(view.x.reversed ? -normal.x : normal.x, view.y.reversed ? -normal.y : normal.y);
        const LabelAnchor anchor = std::abs(page.x) >= std::abs(page.y)
                                       ? (page.x > 0 ? LabelAnchor::Right : LabelAnchor::Left)
                                   : page.y > 0 ? LabelAnchor::Above
                                                : LabelAnchor::Below;
        return {s.name, tip.x, tip.y, anchor};
    }
    const bool underHead = glm::length(view.project(content.head) - centre) < content.arrowLength;
    return {s.name, centre.x, centre.y, underHead ? LabelAnchor::Below : LabelAnchor::Centre};
}

// The screens' names; names that land on one point with one anchor (screens seen edge-on
// behind each other, or facing each other) share one label, "front, back".
std::vector<PlotLabel> screenLabels(const Content& content, const Projection& view) {
    std::vector<PlotLabel> labels;
    for (const display::ScreenFacts& s : content.screens) {
        const PlotLabel label = labelOf(s, content, view);
        const auto same = std::find_if(labels.begin(), labels.end(), [&](const PlotLabel& l) {
            return l.anchor == label.anchor && std::hypot(l.x - label.x, l.y - label.y) < 0.02 * content.arrowLength;
        });
        if (same != labels.end())
            same->text += ", " + s.name;
        else
            labels.push_back(label);
    }
    return labels;
}

std::vector<PlotPoint> projected(const std::vector<glm::dvec3>& points, const Projection& view) {
    std::vector<PlotPoint> out;
    for (const glm::dvec3& p : points) out.push_back(point(view.project(p)));
    return out;
}

// The arrow from `from` along `direction` (unit), unless it points into or out of the panel.
void addArrow(PlotSeries& series, glm::dvec3 from, glm::dvec3 direction, double length, const Projection& view) {
    const glm::dvec2 tail = view.project(from), step = view.project(direction) * length;
    if (glm::length(step) < 0.05 * length) return;
    series.shapes.push_back({point(tail), point(tail + step)});
}

// Fills first, then the shared edges as a wide grey band, then the outlines over the band, so
// that an edge two screens share shows around both screens' lines.
void addScreens(std::vector<PlotSeries>& series, const Content& content, const Projection& view) {
    const std::size_t n = content.screens.size();
    const auto colour = [](std::size_t i) { return kScreenColours[i % std::size(kScreenColours)]; };
    for (std::size_t i = 0; i < n; ++i)
        series.push_back({"",
                          {},
                          SeriesStyle::Filled,
                          {projected(display::outline(content.screens[i]), view)},
                          colour(i),
                          0.0,
                          0.2});
    PlotSeries edges{kSharedEdgeSeries, {}, SeriesStyle::Paths, {}, "#a0a0a0", 9.0};
    for (const display::SharedEdge& e : content.edges) edges.shapes.push_back(projected({e.from, e.to}, view));
    series.push_back(edges);
    for (std::size_t i = 0; i < n; ++i)
        series.push_back({content.screens[i].name,
                          {},
                          SeriesStyle::Outlines,
                          {projected(display::outline(content.screens[i]), view)},
                          colour(i),
                          2.5});
}

void addMarks(std::vector<PlotSeries>& series, const Content& content, const Projection& view) {
    PlotSeries overlaps{kOverlapSeries, {}, SeriesStyle::Filled, {}, "#e41a1c", 0.0, 0.6};
    for (const display::ScreenOverlap& o : content.overlaps) overlaps.shapes.push_back(projected(o.polygon, view));
    PlotSeries normals{kNormalSeries, {}, SeriesStyle::Arrows, {}, "#303030", 2.0};
    for (const display::ScreenFacts& s : content.screens)
        addArrow(normals, s.centre, s.basis.normal, content.arrowLength, view);
    PlotSeries volume{kTrackingSeries, {}, SeriesStyle::Outlines, {}, "#7f7f7f", 1.5};
    if (content.volume) {
        const glm::dvec2 a = view.project((*content.volume)[0]), b = view.project((*content.volume)[1]);
        volume.shapes.push_back({{a.x, a.y}, {b.x, a.y}, {b.x, b.y}, {a.x, b.y}});
    }
    series.insert(series.end(), {overlaps, normals, volume});
}

void addViewer(std::vector<PlotSeries>& series, const Content& content, const Projection& view) {
    series.push_back({kHeadSeries, {point(view.project(content.head))}, SeriesStyle::Markers, {}, "#000000", 2.0});
    PlotSeries direction{kViewSeries, {}, SeriesStyle::Arrows, {}, "#e41a1c", 2.0};
    addArrow(direction, content.head, content.viewDirection, content.arrowLength, view);
    series.push_back(direction);
    const char* eyeColours[] = {"#1f4fd0", "#d01f4f"};
    for (std::size_t i = 0; i < content.eyes.size(); ++i)
        series.push_back({content.eyes[i].first,
                          {point(view.project(content.eyes[i].second))},
                          SeriesStyle::Markers,
                          {},
                          eyeColours[i % 2],
                          0.9});
}

PlotPanel panelOf(const Content& content, const Projection& view, const std::string& title) {
    PlotPanel panel;
    panel.title = title + ": " + view.name;
    panel.x = view.x;
    panel.y = view.y;
    panel.equalScale = true;
    addScreens(panel.series, content, view);
    addMarks(panel.series, content, view);
    addViewer(panel.series, content, view);
    panel.labels = screenLabels(content, view);
    return panel;
}

}  // namespace

Figure displayFigure(const config::DisplayConfig& config, const DisplayFigureOptions& options) {
    const Content content = contentOf(config);
    const std::string title = options.title.empty() ? config.name : options.title;
    const Projection above{"from above (x-z, looking down -y)",
                           {"x", "m", false},
                           {"z (down: towards the viewer)", "m", false, false, true},
                           fromAbove};
    const Projection front{
        "from the front (x-y, looking down -z)", {"x", "m", false}, {"y (up)", "m", false}, fromFront};
    Figure figure;
    // The view from above last: its legend is the figure's, and only there does the default view
    // direction (along -z) show as an arrow.
    figure.panels = {panelOf(content, front, title), panelOf(content, above, title)};
    figure.width = options.width;
    figure.height = options.height;
    figure.legendWidth = options.legendWidth;
    figure.note =
        "stereo " + std::string(config::toString(config.stereo)) + ", near " +
        config::formatNumber(config.viewer.near) + " m, far " +
        (std::isinf(config.viewer.far) ? std::string("infinite") : config::formatNumber(config.viewer.far) + " m");
    return figure;
}

}  // namespace cavewall::bench
