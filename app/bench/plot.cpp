#include "app/bench/plot.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <cstdio>

namespace cavewall::bench {

namespace {

// 3x5 glyphs, one row per 3 bits (bit 2 = left column), top row first.
const unsigned char* glyph(char c) {
    static const unsigned char kDigits[10][5] = {{7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7},
                                                 {5, 5, 7, 1, 1}, {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1},
                                                 {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
    static const unsigned char kDot[5] = {0, 0, 0, 0, 2}, kMinus[5] = {0, 0, 7, 0, 0}, kE[5] = {7, 4, 7, 4, 7},
                               kPlus[5] = {0, 2, 7, 2, 0};
    if (c >= '0' && c <= '9') return kDigits[c - '0'];
    if (c == '.') return kDot;
    if (c == '-') return kMinus;
    if (c == 'e') return kE;
    if (c == '+') return kPlus;
    return nullptr;
}

void setPixel(scenes::Image& image, int x, int y, const unsigned char rgb[3]) {
    if (x < 0 || y < 0 || x >= image.width || y >= image.height) return;
    std::uint8_t* p = &image.rgba[(static_cast<std::size_t>(y) * image.width + x) * 4];
    p[0] = rgb[0];
    p[1] = rgb[1];
    p[2] = rgb[2];
    p[3] = 255;
}

void fillRect(scenes::Image& image, int x0, int y0, int w, int h, const unsigned char rgb[3]) {
    for (int y = y0; y < y0 + h; ++y)
        for (int x = x0; x < x0 + w; ++x) setPixel(image, x, y, rgb);
}

void drawLine(scenes::Image& image, int x0, int y0, int x1, int y1, const unsigned char rgb[3]) {
    const int steps = std::max(std::abs(x1 - x0), std::abs(y1 - y0));
    for (int i = 0; i <= steps; ++i) {
        const double t = steps ? static_cast<double>(i) / steps : 0.0;
        setPixel(image, static_cast<int>(std::lround(x0 + t * (x1 - x0))),
                 static_cast<int>(std::lround(y0 + t * (y1 - y0))), rgb);
    }
}

// A "nice" axis end: the smallest 1, 1.5, 2, 2.5, 3, 4, 5, 6 or 8 x 10^k at or above `value`
// (> 0), so that five ticks have short labels and the points fill most of the axis.
double niceCeil(double value) {
    if (!(value > 0.0) || !std::isfinite(value)) return 1.0;
    const double p = std::pow(10.0, std::floor(std::log10(value)));
    for (double m : {1.0, 1.5, 2.0, 2.5, 3.0, 4.0, 5.0, 6.0, 8.0, 10.0})
        if (m * p >= value * (1 - 1e-12)) return m * p;
    return 10.0 * p;
}

std::string tickText(double v) {
    char buffer[32];
    // Up to six digits in full ("2400", not "2.4e+03", which overflows the left margin).
    std::snprintf(buffer, sizeof buffer, v >= 1000.0 && v < 1e6 ? "%.0f" : "%.3g", v);
    return buffer;
}

}  // namespace

void drawText(scenes::Image& image, int x, int y, const std::string& text, int scale, const unsigned char rgb[3]) {
    for (char c : text) {
        if (const unsigned char* g = glyph(c))
            for (int row = 0; row < 5; ++row)
                for (int col = 0; col < 3; ++col)
                    if (g[row] & (4 >> col)) fillRect(image, x + col * scale, y + row * scale, scale, scale, rgb);
        x += 4 * scale;
    }
}

namespace {

// The plot area [left, right] x [top, bottom] in pixels for data in [0, maxX] x [0, maxY]: grid
// lines and tick labels at fifths, and the two axes.
struct Axes {
    int left, right, top, bottom;
    double maxX, maxY;
    int px(double x) const { return left + static_cast<int>(std::lround(x / maxX * (right - left))); }
    int py(double y) const { return bottom - static_cast<int>(std::lround(y / maxY * (bottom - top))); }
};

Axes drawAxes(scenes::Image& image, int left, int right, int top, int bottom, double maxX, double maxY) {
    static const unsigned char kAxis[3] = {40, 40, 40}, kGrid[3] = {225, 225, 225};
    const Axes a{left, right, top, bottom, maxX, maxY};
    constexpr int kTicks = 5;
    for (int i = 0; i <= kTicks; ++i) {
        const double fx = maxX * i / kTicks, fy = maxY * i / kTicks;
        drawLine(image, a.px(fx), top, a.px(fx), bottom, kGrid);
        drawLine(image, left, a.py(fy), right, a.py(fy), kGrid);
        const std::string tx = tickText(fx), ty = tickText(fy);
        drawText(image, a.px(fx) - static_cast<int>(tx.size()) * 4, bottom + 8, tx, 2, kAxis);
        drawText(image, left - 6 - static_cast<int>(ty.size()) * 8, a.py(fy) - 5, ty, 2, kAxis);
    }
    drawLine(image, left, bottom, right, bottom, kAxis);
    drawLine(image, left, top, left, bottom, kAxis);
    return a;
}

}  // namespace

scenes::Image plotTradeOff(const std::vector<PlotPoint>& points, int width, int height) {
    assert(width >= 160 && height >= 120);
    static const unsigned char kWhite[3] = {255, 255, 255}, kBlue[3] = {40, 90, 200}, kRed[3] = {210, 30, 30};
    scenes::Image image{"bench.png", width, height,
                        std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    fillRect(image, 0, 0, width, height, kWhite);
    const int left = 56, right = width - 20, top = 16, bottom = height - 36;
    double maxX = 0.0, maxY = 0.0;
    for (const PlotPoint& p : points) {
        maxX = std::max(maxX, p.x);
        maxY = std::max(maxY, p.y);
    }
    maxX = niceCeil(maxX * 1.05);
    maxY = niceCeil(maxY * 1.05);
    const Axes axes = drawAxes(image, left, right, top, bottom, maxX, maxY);
    const auto px = [&](double x) { return axes.px(x); };
    const auto py = [&](double y) { return axes.py(y); };
    const PlotPoint* previous = nullptr;
    std::vector<const PlotPoint*> front;
    for (const PlotPoint& p : points)
        if (p.front) front.push_back(&p);
    std::sort(front.begin(), front.end(), [](auto a, auto b) { return a->x < b->x; });
    for (const PlotPoint* p : front) {
        if (previous) drawLine(image, px(previous->x), py(previous->y), px(p->x), py(p->y), kRed);
        previous = p;
    }
    for (const PlotPoint& p : points) {
        const unsigned char* colour = p.front ? kRed : kBlue;
        fillRect(image, px(p.x) - 3, py(p.y) - 3, 7, 7, colour);
        drawText(image, px(p.x) + 6, py(p.y) - 12, std::to_string(p.label), 2, colour);
    }
    return image;
}

scenes::Image plotSeries(const std::vector<PlotSeries>& series, int width, int height) {
    assert(width >= 160 && height >= 120);
    static const unsigned char kWhite[3] = {255, 255, 255};
    static const unsigned char kColours[4][3] = {{40, 90, 200}, {210, 30, 30}, {30, 150, 60}, {230, 130, 20}};
    scenes::Image image{"plot.png", width, height,
                        std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4)};
    fillRect(image, 0, 0, width, height, kWhite);
    const int left = 64, right = width - 40, top = 16, bottom = height - 36;
    double maxX = 0.0, maxY = 0.0;
    for (const PlotSeries& s : series)
        for (const PlotPoint& p : s.points) {
            maxX = std::max(maxX, p.x);
            maxY = std::max(maxY, p.y);
        }
    maxX = niceCeil(maxX * 1.05);
    maxY = niceCeil(maxY * 1.05);
    const Axes axes = drawAxes(image, left, right, top, bottom, maxX, maxY);
    const auto px = [&](double x) { return axes.px(x); };
    const auto py = [&](double y) { return axes.py(y); };
    for (const PlotSeries& s : series) {
        const unsigned char* colour = kColours[((s.label % 4) + 4) % 4];
        std::vector<PlotPoint> points = s.points;
        std::sort(points.begin(), points.end(), [](const PlotPoint& a, const PlotPoint& b) { return a.x < b.x; });
        for (std::size_t i = 0; i < points.size(); ++i) {
            fillRect(image, px(points[i].x) - 3, py(points[i].y) - 3, 7, 7, colour);
            if (i > 0)
                drawLine(image, px(points[i - 1].x), py(points[i - 1].y), px(points[i].x), py(points[i].y), colour);
        }
        if (!points.empty())
            drawText(image, px(points.back().x) + 6, py(points.back().y) - 12, std::to_string(s.label), 2, colour);
    }
    return image;
}

}  // namespace cavewall::bench
