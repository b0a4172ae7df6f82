#include "walls/plan_diagram.h"

#include <algorithm>
#include <cmath>

namespace cavewall::walls {
namespace {

using Rgb = glm::dvec3;

struct Canvas {
    scenes::Image& image;
    glm::ivec2 origin;  // panel's top-left pixel
    glm::ivec2 size;    // panel's size in pixels
    glm::dvec2 worldMin;
    double scale;  // pixels per metre

    glm::dvec2 toPixel(glm::dvec2 p) const { return glm::dvec2(origin) + 8.0 + (p - worldMin) * scale; }

    void blend(int x, int y, Rgb c, double a) {
        if (x < origin.x || y < origin.y || x >= origin.x + size.x || y >= origin.y + size.y) return;
        std::uint8_t* px = &image.rgba[(std::size_t(y) * image.width + x) * 4];
        for (int i = 0; i < 3; ++i) px[i] = std::uint8_t(std::lround(px[i] * (1 - a) + c[i] * a));
    }
    void fill(const Polygon2& world, Rgb c, double a) {
        Polygon2 poly;
        for (const glm::dvec2& p : world) poly.push_back(toPixel(p));
        if (poly.size() < 3) return;
        glm::dvec2 lo(1e30), hi(-1e30);
        for (const glm::dvec2& p : poly) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
        for (int y = int(std::floor(lo.y)); y <= int(std::ceil(hi.y)); ++y)
            for (int x = int(std::floor(lo.x)); x <= int(std::ceil(hi.x)); ++x)
                if (containsConvex(poly, {x + 0.5, y + 0.5}, 0.0)) blend(x, y, c, a);
    }
    void line(glm::dvec2 a, glm::dvec2 b, Rgb c, int thickness) {
        const glm::dvec2 pa = toPixel(a), pb = toPixel(b);
        const int steps = std::max(1, int(glm::length(pb - pa) * 2));
        for (int i = 0; i <= steps; ++i) dot(pa + (pb - pa) * (double(i) / steps), thickness, c);
    }
    void outline(const Polygon2& world, Rgb c, int thickness) {
        for (std::size_t i = 0; i < world.size(); ++i) line(world[i], world[(i + 1) % world.size()], c, thickness);
    }
    void dot(glm::dvec2 pixel, int size, Rgb c) {
        const int x0 = int(std::floor(pixel.x - 0.5 * (size - 1))), y0 = int(std::floor(pixel.y - 0.5 * (size - 1)));
        for (int y = y0; y < y0 + size; ++y)
            for (int x = x0; x < x0 + size; ++x) blend(x, y, c, 1.0);
    }
};

Rgb zoneColour(const Zone& z) {
    if (z.kind == ZoneKind::Geometry) return {220, 80, 70};
    if (z.kind == ZoneKind::Blend) return {240, 205, 60};
    const double shade[] = {0, 40, 80};
    return {70 + shade[z.textures[0] % 3], 170 + shade[(z.textures[0] / 3) % 2] * 0.5, 80};
}

void drawPanel(Canvas& c, const Plan& plan, const scenes::SceneDescription& d, const scenes::Scene* scene, int wall) {
    for (const Zone& z : plan.zones)
        if (z.wall == wall) c.fill(z.floorPolygon, zoneColour(z), 0.85);
    for (const scenes::Cell& cell : d.cells) c.outline(cell.region, {150, 150, 150}, 1);
    if (scene)
        for (const scenes::Object& o : scene->objects) {
            if (o.worldBounds.empty() || o.role == scenes::Role::Structure) continue;
            const glm::dvec3 lo = o.worldBounds.min, hi = o.worldBounds.max;
            c.outline({{lo.x, lo.z}, {hi.x, lo.z}, {hi.x, hi.z}, {lo.x, hi.z}}, {90, 90, 90}, 1);
        }
    for (const scenes::RealWall& w : d.realWalls)
        c.line({w.lowerLeft.x, w.lowerLeft.z}, {w.lowerRight.x, w.lowerRight.z}, {0, 0, 0}, 3);
    for (int i = 0; i < int(d.walls.size()); ++i) {
        const scenes::VirtualWall& w = d.walls[i];
        c.line({w.lowerLeft.x, w.lowerLeft.z}, {w.lowerRight.x, w.lowerRight.z},
               i == wall ? Rgb{20, 40, 200} : Rgb{120, 170, 240}, i == wall ? 3 : 2);
    }
    for (const Texture& t : plan.textures)
        if (t.wall == wall) c.dot(c.toPixel({t.samplingPoint.x, t.samplingPoint.z}), 3, {0, 0, 0});
}

}  // namespace

scenes::Image planDiagram(const Plan& plan, const scenes::SceneDescription& d, const scenes::Scene* scene,
                          int panelSize) {
    const int panels = std::max<int>(1, int(plan.walls.size()));
    const int columns = int(std::ceil(std::sqrt(double(panels))));
    const int rows = (panels + columns - 1) / columns;
    glm::dvec2 lo(1e30), hi(-1e30);
    for (const scenes::Cell& cell : d.cells)
        for (const glm::dvec2& p : cell.region) {
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
        }
    for (const scenes::VirtualWall& w : d.walls)
        for (glm::dvec3 p : {w.lowerLeft, w.lowerRight}) {
            lo = glm::min(lo, {p.x, p.z});
            hi = glm::max(hi, {p.x, p.z});
        }
    if (lo.x > hi.x) {
        lo = glm::dvec2(-1);
        hi = glm::dvec2(1);
    }
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, 1e-3});
    const double scale = (panelSize - 16) / extent;
    // Panels are panelSize wide and as high as the floor plan needs.
    const glm::ivec2 panel(panelSize, std::min(panelSize, int(std::ceil((hi.y - lo.y) * scale)) + 16));
    scenes::Image image;
    image.name = "plan diagram";
    image.width = columns * panel.x;
    image.height = rows * panel.y;
    image.rgba.assign(std::size_t(image.width) * image.height * 4, 255);
    for (int p = 0; p < panels; ++p) {
        Canvas c{image, {(p % columns) * panel.x, (p / columns) * panel.y}, panel, lo, scale};
        drawPanel(c, plan, d, scene, plan.walls.empty() ? -1 : p);
        c.outline({lo - 0.5 * 8 / c.scale,
                   {hi.x + 4 / c.scale, lo.y - 4 / c.scale},
                   hi + 0.5 * 8 / c.scale,
                   {lo.x - 4 / c.scale, hi.y + 4 / c.scale}},
                  {200, 200, 200}, 1);
    }
    return image;
}

}  // namespace cavewall::walls
