#include "scenes/bvh.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::scenes {

Frustum::Frustum(const glm::dmat4& m) {
    const glm::dvec4 r0(m[0][0], m[1][0], m[2][0], m[3][0]), r1(m[0][1], m[1][1], m[2][1], m[3][1]);
    const glm::dvec4 r2(m[0][2], m[1][2], m[2][2], m[3][2]), r3(m[0][3], m[1][3], m[2][3], m[3][3]);
    // -w <= x <= w, -w <= y <= w, 0 <= z <= w (reversed-Z: z = w at the near plane).
    for (const glm::dvec4& p : {r3 + r0, r3 - r0, r3 + r1, r3 - r1, r2, r3 - r2}) {
        const double len = glm::length(glm::dvec3(p));
        // An infinite far plane leaves z = near (no xyz part): always satisfied, nothing to test.
        if (!(len > 1e-300) || !std::isfinite(len)) continue;
        _planes[_count++] = p / len;
    }
}

bool Frustum::intersects(const Bounds& b) const {
    if (b.empty()) return false;
    for (int i = 0; i < _count; ++i) {
        const glm::dvec4& p = _planes[i];
        // The corner furthest along the plane normal: if even it is outside, the box is.
        const glm::dvec3 far(p.x >= 0 ? b.max.x : b.min.x, p.y >= 0 ? b.max.y : b.min.y, p.z >= 0 ? b.max.z : b.min.z);
        if (glm::dot(glm::dvec3(p), far) + p.w < 0.0) return false;
    }
    return true;
}

bool Frustum::contains(const Bounds& b) const {
    if (b.empty()) return false;
    for (int i = 0; i < _count; ++i) {
        const glm::dvec4& p = _planes[i];
        const glm::dvec3 near(p.x >= 0 ? b.min.x : b.max.x, p.y >= 0 ? b.min.y : b.max.y, p.z >= 0 ? b.min.z : b.max.z);
        if (glm::dot(glm::dvec3(p), near) + p.w < 0.0) return false;
    }
    return true;
}

Bvh::Bvh(const Scene& scene) {
    std::vector<Bounds> bounds;
    std::vector<std::vector<int>> cells;
    for (const Object& o : scene.objects) {
        bounds.push_back(o.worldBounds);
        cells.push_back(cellsOf(o));
    }
    *this = Bvh(bounds, std::move(cells));
}

namespace {

constexpr int kNoCell = std::numeric_limits<int>::min();
constexpr int kSeveralCells = kNoCell + 1;

// Bvh::_soleCell of an object with the cells `own`.
int soleCell(const std::vector<int>& own) {
    if (own.empty()) return kNoCell;
    return own.size() == 1 && own[0] > kSeveralCells ? own[0] : kSeveralCells;
}

std::vector<std::vector<int>> singleCells(const std::vector<int>& cells) {
    std::vector<std::vector<int>> sets;
    for (int c : cells) sets.push_back(c >= 0 ? std::vector<int>{c} : std::vector<int>{});
    return sets;
}

}  // namespace

Bvh::Bvh(const std::vector<Bounds>& bounds, std::vector<int> cells) : Bvh(bounds, singleCells(cells)) {}

Bvh::Bvh(const std::vector<Bounds>& bounds, std::vector<std::vector<int>> cellSets)
    : _cells(std::move(cellSets)), _bounds(bounds) {
    _cells.resize(bounds.size());
    _soleCell.reserve(_cells.size());
    for (std::vector<int>& own : _cells) {
        _soleCell.push_back(soleCell(own));
        if (_soleCell.back() != kSeveralCells) own = {};
    }
    _order.resize(bounds.size());
    for (std::size_t i = 0; i < bounds.size(); ++i) _order[i] = static_cast<int>(i);
    _nodes.reserve(2 * bounds.size());
    if (!bounds.empty()) build(0, static_cast<int>(bounds.size()), bounds);
}

int Bvh::build(int first, int count, const std::vector<Bounds>& bounds) {
    const int index = static_cast<int>(_nodes.size());
    _nodes.push_back({});
    Bounds box, centres;
    for (int i = first; i < first + count; ++i) {
        box.add(bounds[_order[i]]);
        if (!bounds[_order[i]].empty()) centres.add(bounds[_order[i]].centre());
    }
    _nodes[index].bounds = box;
    _nodes[index].first = first;
    _nodes[index].count = count;
    constexpr int kLeafSize = 4;
    if (count <= kLeafSize || centres.empty()) return index;
    // Median split along the widest spread of centres: balanced, O(n log n) overall.
    const glm::dvec3 spread = centres.size();
    const int axis = spread.x >= spread.y && spread.x >= spread.z ? 0 : spread.y >= spread.z ? 1 : 2;
    const int mid = first + count / 2;
    auto key = [&](int o) { return bounds[o].empty() ? 0.0 : bounds[o].centre()[axis]; };
    std::nth_element(_order.begin() + first, _order.begin() + mid, _order.begin() + first + count,
                     [&](int a, int b) { return key(a) < key(b) || (key(a) == key(b) && a < b); });
    const int left = build(first, mid - first, bounds);
    const int right = build(mid, first + count - mid, bounds);
    _nodes[index].left = left;
    _nodes[index].right = right;
    return index;
}

bool Bvh::kept(int object, const std::vector<bool>* cells) const {
    const int sole = _soleCell[object];
    if (!cells || sole == kNoCell) return true;
    auto drawn = [&](int c) { return c >= 0 && c < static_cast<int>(cells->size()) && (*cells)[c]; };
    if (sole != kSeveralCells) return drawn(sole);
    const std::vector<int>& own = _cells[object];
    return std::any_of(own.begin(), own.end(), drawn);
}

void Bvh::addRange(const Node& node, std::vector<int>& out, const std::vector<bool>* cells) const {
    for (int i = node.first; i < node.first + node.count; ++i) {
        const int o = _order[i];
        if (_bounds[o].empty() || !kept(o, cells)) continue;
        out.push_back(o);
    }
}

std::vector<int> Bvh::cull(const glm::dmat4& clipFromWorld, const std::vector<bool>* cells) const {
    std::vector<int> out;
    cull(clipFromWorld, out, cells);
    return out;
}

void Bvh::cull(const glm::dmat4& clipFromWorld, std::vector<int>& out, const std::vector<bool>* cells) const {
    out.clear();
    if (_nodes.empty()) return;
    const Frustum frustum(clipFromWorld);
    int stack[128];  // depth of a median-split tree is about log2(n / 4): far below 128
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& node = _nodes[stack[--top]];
        if (!frustum.intersects(node.bounds)) continue;
        // Objects lie inside their node's box: a node inside every plane keeps them all.
        if (node.left < 0 || frustum.contains(node.bounds)) {
            if (node.left >= 0) {
                addRange(node, out, cells);
                continue;
            }
            for (int i = node.first; i < node.first + node.count; ++i) {
                const int o = _order[i];
                if (!kept(o, cells)) continue;
                if (frustum.intersects(_bounds[o])) out.push_back(o);
            }
            continue;
        }
        stack[top++] = node.right;
        stack[top++] = node.left;
    }
}

}  // namespace cavewall::scenes
