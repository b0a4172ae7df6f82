#include "display/window_layout.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>

namespace cavewall::display {
namespace {

// The grid for `count` windows of at most `largest` content pixels (plus `titleBar` above each)
// in `area`: the columns and rows that keep the largest scale, and that scale (<= 1).
struct Grid {
    int columns = 1, rows = 1;
    double scale = 1.0;
};

Grid bestGrid(int count, glm::ivec2 largest, int titleBar, glm::ivec2 area) {
    Grid best{count, 1, -1.0};
    for (int columns = 1; columns <= count; ++columns) {
        const int rows = (count + columns - 1) / columns;
        const double cellW = area.x / columns;  // whole pixels, as the cells are placed
        const double cellH = area.y / rows - titleBar;
        const double scale = std::min({1.0, cellW / largest.x, cellH / largest.y});
        if (scale > best.scale + 1e-12) best = {columns, rows, scale};
    }
    best.scale = std::max(best.scale, 1.0 / std::max(largest.x, largest.y));  // at least one pixel
    return best;
}

}  // namespace

std::vector<WindowPlacement> layoutWindows(const std::vector<WindowWish>& wishes,
                                           const std::vector<MonitorArea>& monitors) {
    std::vector<WindowPlacement> out(wishes.size());
    std::vector<std::vector<std::size_t>> tiled(monitors.size());
    for (std::size_t i = 0; i < wishes.size(); ++i) {
        const WindowWish& w = wishes[i];
        if (w.monitor < 0 || w.monitor >= static_cast<int>(monitors.size()))
            throw Error("screen '" + w.name + "': window.monitor: expected a monitor index in [0, " +
                        std::to_string(static_cast<int>(monitors.size()) - 1) + "] (" +
                        std::to_string(monitors.size()) + (monitors.size() == 1 ? " monitor" : " monitors") +
                        "), got " + std::to_string(w.monitor));
        const MonitorArea& m = monitors[static_cast<std::size_t>(w.monitor)];
        if (w.fullscreen)
            out[i] = {m.position, m.size,
                      std::min(static_cast<double>(m.size.x) / w.size.x, static_cast<double>(m.size.y) / w.size.y)};
        else if (w.position)
            out[i] = {m.position + *w.position, w.size, 1.0};
        else
            tiled[static_cast<std::size_t>(w.monitor)].push_back(i);
    }
    for (std::size_t m = 0; m < monitors.size(); ++m) {
        const std::vector<std::size_t>& group = tiled[m];
        if (group.empty()) continue;
        glm::ivec2 largest(1);
        bool decorated = false;
        for (std::size_t i : group) {
            largest = glm::max(largest, wishes[i].size);
            decorated = decorated || !wishes[i].borderless;
        }
        const int titleBar = decorated ? kTitleBarPixels : 0;
        const Grid grid = bestGrid(static_cast<int>(group.size()), largest, titleBar, monitors[m].size);
        const glm::ivec2 cell(monitors[m].size.x / grid.columns, monitors[m].size.y / grid.rows);
        for (std::size_t k = 0; k < group.size(); ++k) {
            const WindowWish& w = wishes[group[k]];
            const glm::ivec2 size = glm::max(glm::ivec2(1), glm::ivec2(glm::floor(glm::dvec2(w.size) * grid.scale)));
            const glm::ivec2 at(static_cast<int>(k) % grid.columns, static_cast<int>(k) / grid.columns);
            out[group[k]] = {monitors[m].position + at * cell + glm::ivec2(0, w.borderless ? 0 : titleBar), size,
                             static_cast<double>(size.x) / w.size.x};
        }
    }
    return out;
}

glm::ivec4 fitImage(glm::ivec2 image, glm::ivec2 window) {
    if (image.x <= 0 || image.y <= 0 || window.x <= 0 || window.y <= 0) return {0, 0, 0, 0};
    // Products in 64 bits: the rectangle's width at the window's height, and its height at the
    // window's width, rounded to the nearest pixel.
    const auto along = [](long long a, long long b, long long c) { return static_cast<int>((a * b + c / 2) / c); };
    glm::ivec2 size = window;
    if (const int width = along(window.y, image.x, image.y); width < window.x)
        size.x = width;
    else if (const int height = along(window.x, image.y, image.x); height < window.y)
        size.y = height;
    if (window.x - size.x <= 1 && window.y - size.y <= 1) size = window;
    size = glm::max(size, glm::ivec2(1));
    const glm::ivec2 origin = (window - size) / 2;
    return {origin.x, origin.y, origin.x + size.x, origin.y + size.y};
}

}  // namespace cavewall::display
