#include "walls/walk_grid.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>
#include <limits>

namespace cavewall::walls {

namespace {

// True when p lies inside triangle (a, b, c) or on its border, in either winding.
bool inside(glm::dvec2 p, const glm::dvec2 (&t)[3]) {
    auto side = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 q) {
        return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x);
    };
    const double d0 = side(t[0], t[1], p), d1 = side(t[1], t[2], p), d2 = side(t[2], t[0], p);
    return (d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) || (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0);
}

// Heights of the facets, up and down, per cell; `up` marks the upward ones.
struct Sample {
    double y = 0.0;
    bool up = true;
};

}  // namespace

std::int64_t WalkGrid::key(long long i, long long j) const {
    return (static_cast<std::int64_t>(i) << 32) ^ static_cast<std::int64_t>(static_cast<std::uint32_t>(j));
}

WalkGrid::WalkGrid(const std::vector<Facet>& facets, double bottomY, double topY, const WalkGridOptions& options)
    : options_(options) {
    assert(options.cell > 0.0 && bottomY <= topY);
    const double c = options.cell;
    std::unordered_map<std::int64_t, std::vector<Sample>> samples;
    std::unordered_map<std::int64_t, glm::dvec2> centres;
    for (const Facet& f : facets) {
        if (f.y < bottomY || f.y > topY) continue;
        const long long i0 = std::llround(std::floor(f.lo.x / c)), i1 = std::llround(std::floor(f.hi.x / c));
        const long long j0 = std::llround(std::floor(f.lo.y / c)), j1 = std::llround(std::floor(f.hi.y / c));
        bool any = false;
        for (long long i = i0; i <= i1; ++i)
            for (long long j = j0; j <= j1; ++j) {
                const glm::dvec2 centre((i + 0.5) * c, (j + 0.5) * c);
                if (!inside(centre, f.corners)) continue;
                samples[key(i, j)].push_back({f.y + glm::dot(f.slope, centre - f.centre), f.up});
                centres[key(i, j)] = centre;
                any = true;
            }
        if (!any) {
            const long long i = std::llround(std::floor(f.centre.x / c)), j = std::llround(std::floor(f.centre.y / c));
            samples[key(i, j)].push_back({f.y, f.up});
        }
    }
    std::vector<std::int64_t> cells;
    for (const auto& [k, list] : samples) cells.push_back(k);
    std::sort(cells.begin(), cells.end());  // node numbers do not depend on the hash order
    for (std::int64_t k : cells) {
        std::vector<Sample>& list = samples[k];
        std::sort(list.begin(), list.end(), [](const Sample& a, const Sample& b) { return a.y < b.y; });
        std::vector<double> levels;
        for (const Sample& s : list) {
            if (!s.up) continue;
            if (!levels.empty() && s.y - levels.back() < options.levelGap)
                levels.back() = s.y;
            else
                levels.push_back(s.y);
        }
        for (double y : levels) {
            const bool blocked = std::any_of(list.begin(), list.end(), [&](const Sample& s) {
                return s.y > y + options.clearance && s.y < y + options.headroom;
            });
            if (blocked) continue;
            byCell_[k].push_back(static_cast<int>(nodes_.size()));
            nodes_.push_back({k, y});
        }
    }
}

glm::dvec3 WalkGrid::point(int node) const {
    const std::int64_t k = nodes_[node].cell;
    const long long i = k >> 32;
    const long long j = static_cast<std::int32_t>(static_cast<std::uint32_t>(k & 0xffffffff));
    return {(i + 0.5) * options_.cell, nodes_[node].y, (j + 0.5) * options_.cell};
}

template <class Target>
std::vector<int> WalkGrid::search(const std::vector<int>& sources, Target target) const {
    std::vector<int> parent(nodes_.size(), -2);
    std::deque<int> queue;
    for (int s : sources) {
        parent[s] = -1;
        queue.push_back(s);
    }
    while (!queue.empty()) {
        const int n = queue.front();
        queue.pop_front();
        if (target(n)) {
            std::vector<int> walk;
            for (int at = n; at >= 0; at = parent[at]) walk.push_back(at);
            std::reverse(walk.begin(), walk.end());
            return walk;
        }
        const std::int64_t k = nodes_[n].cell;
        const long long i = k >> 32;
        const long long j = static_cast<std::int32_t>(static_cast<std::uint32_t>(k & 0xffffffff));
        for (const auto& [di, dj] : {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
            const auto next = byCell_.find(key(i + di, j + dj));
            if (next == byCell_.end()) continue;
            for (int m : next->second)
                if (parent[m] == -2 && std::abs(nodes_[m].y - nodes_[n].y) <= options_.maxStep) {
                    parent[m] = n;
                    queue.push_back(m);
                }
        }
    }
    return {};
}

std::vector<glm::dvec3> WalkGrid::simplified(const std::vector<int>& walk) const {
    std::vector<glm::dvec3> points;
    for (int n : walk) points.push_back(point(n));
    if (points.size() <= 2) return points;
    // From each kept point, the farthest point reached in one direction across with every point
    // between within a step of the straight line in height.
    auto straight = [&](std::size_t from, std::size_t to) {
        const glm::dvec2 d(points[from + 1].x - points[from].x, points[from + 1].z - points[from].z);
        for (std::size_t k = from + 1; k <= to; ++k) {
            const glm::dvec2 e(points[k].x - points[k - 1].x, points[k].z - points[k - 1].z);
            const double t = double(k - from) / double(to - from);
            const double y = points[from].y + t * (points[to].y - points[from].y);
            if (e != d || std::abs(points[k].y - y) > 0.5 * options_.maxStep) return false;
        }
        return true;
    };
    std::vector<glm::dvec3> out{points.front()};
    std::size_t at = 0;
    while (at + 1 < points.size()) {
        std::size_t to = at + 1;
        while (to + 1 < points.size() && straight(at, to + 1)) ++to;
        out.push_back(points[to]);
        at = to;
    }
    return out;
}

std::vector<glm::dvec3> WalkGrid::climb(double fromY, double toY) const {
    std::vector<int> sources;
    for (std::size_t n = 0; n < nodes_.size(); ++n)
        if (std::abs(nodes_[n].y - fromY) <= options_.tolerance) sources.push_back(static_cast<int>(n));
    if (sources.empty()) return {};
    const std::vector<int> walk =
        search(sources, [&](int n) { return std::abs(nodes_[n].y - toY) <= options_.tolerance; });
    return simplified(walk);
}

int WalkGrid::nearest(glm::dvec3 p) const {
    int best = -1;
    double bestDistance = std::numeric_limits<double>::infinity();
    const long long i0 = std::llround(std::floor(p.x / options_.cell));
    const long long j0 = std::llround(std::floor(p.z / options_.cell));
    const long long reach = std::llround(std::ceil(2.0 / options_.cell));
    for (long long i = i0 - reach; i <= i0 + reach; ++i)
        for (long long j = j0 - reach; j <= j0 + reach; ++j) {
            const auto at = byCell_.find(key(i, j));
            if (at == byCell_.end()) continue;
            for (int n : at->second) {
                const glm::dvec3 q = point(n);
                if (std::abs(q.y - p.y) > 0.5) continue;
                const double d = glm::length(glm::dvec2(q.x - p.x, q.z - p.z));
                if (d <= 2.0 && d < bestDistance) {
                    best = n;
                    bestDistance = d;
                }
            }
        }
    return best;
}

std::vector<glm::dvec3> WalkGrid::route(glm::dvec3 from, glm::dvec3 to) const {
    const int a = nearest(from), b = nearest(to);
    if (a < 0 || b < 0) return {};
    return simplified(search({a}, [&](int n) { return n == b; }));
}

}  // namespace cavewall::walls
