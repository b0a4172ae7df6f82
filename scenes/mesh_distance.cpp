#include "scenes/mesh_distance.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numeric>
#include <vector>

namespace cavewall::scenes {

namespace {

struct Triangle {
    glm::dvec3 a, b, c;
};

// Distance from p to the triangle (closest point by Voronoi regions: Ericson, Real-Time
// Collision Detection, 5.1.5).
double distanceToTriangle(glm::dvec3 p, const Triangle& t) {
    const glm::dvec3 ab = t.b - t.a, ac = t.c - t.a, ap = p - t.a;
    const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) return glm::length(ap);
    const glm::dvec3 bp = p - t.b;
    const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) return glm::length(bp);
    const double vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return glm::length(p - (t.a + d1 / (d1 - d3) * ab));
    const glm::dvec3 cp = p - t.c;
    const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) return glm::length(cp);
    const double vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return glm::length(p - (t.a + d2 / (d2 - d6) * ac));
    const double va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && d4 - d3 >= 0.0 && d5 - d6 >= 0.0)
        return glm::length(p - (t.b + (d4 - d3) / ((d4 - d3) + (d5 - d6)) * (t.c - t.b)));
    const double denom = va + vb + vc;
    if (!(denom > 0.0)) return std::min({glm::length(ap), glm::length(bp), glm::length(cp)});  // degenerate
    return glm::length(p - (t.a + ab * (vb / denom) + ac * (vc / denom)));
}

// A bounding-volume hierarchy over triangles for nearest-surface queries.
class TriangleTree {
public:
    explicit TriangleTree(std::vector<Triangle> triangles) : _triangles(std::move(triangles)) {
        std::vector<int> order(_triangles.size());
        std::iota(order.begin(), order.end(), 0);
        if (!order.empty()) {
            _nodes.push_back({});
            build(order, 0, static_cast<int>(order.size()), 0);
        }
        std::vector<Triangle> sorted;
        for (int i : order) sorted.push_back(_triangles[i]);
        _triangles = std::move(sorted);
    }

    // The distance from p to the surface, or any value <= `enough` once one is certain not to
    // exceed it (a Hausdorff maximum only needs the samples farther than the largest so far).
    // `hint`: a triangle likely near p (the last query's nearest, for samples taken in order);
    // it starts the search with a tight bound. Updated to this query's nearest.
    double distance(glm::dvec3 p, int& hint, double enough = 0.0) const {
        double best = std::numeric_limits<double>::infinity();
        if (_nodes.empty()) return best;
        if (hint >= 0 && hint < static_cast<int>(_triangles.size())) best = distanceToTriangle(p, _triangles[hint]);
        if (best <= enough) return best;
        std::array<int, 128> stack;
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& n = _nodes[stack[--top]];
            if (boxDistance(n, p) >= best) continue;
            if (n.count > 0) {
                for (int i = n.first; i < n.first + n.count; ++i) {
                    const double d = distanceToTriangle(p, _triangles[i]);
                    if (d < best) {
                        best = d;
                        hint = i;
                    }
                }
                if (best <= enough) return best;
                continue;
            }
            // Nearer child last, so it is popped first.
            const int l = n.first, r = n.first + 1;
            const bool leftNearer = boxDistance(_nodes[l], p) < boxDistance(_nodes[r], p);
            stack[top++] = leftNearer ? r : l;
            stack[top++] = leftNearer ? l : r;
        }
        return best;
    }

private:
    struct Node {
        glm::dvec3 lo, hi;
        int first = 0, count = 0;  // leaf: triangles [first, first + count); inner: children first, first + 1
    };
    static constexpr int kLeafSize = 4;

    static double boxDistance(const Node& n, glm::dvec3 p) {
        const glm::dvec3 d = glm::max(glm::max(n.lo - p, p - n.hi), glm::dvec3(0.0));
        return glm::length(d);
    }

    glm::dvec3 centre(int i) const { return (_triangles[i].a + _triangles[i].b + _triangles[i].c) / 3.0; }

    // Fills the node at _nodes[index] with order[begin, end), adding its children.
    void build(std::vector<int>& order, int begin, int end, int index) {
        Node n;
        n.lo = glm::dvec3(std::numeric_limits<double>::infinity());
        n.hi = -n.lo;
        for (int k = begin; k < end; ++k)
            for (const glm::dvec3& v : {_triangles[order[k]].a, _triangles[order[k]].b, _triangles[order[k]].c}) {
                n.lo = glm::min(n.lo, v);
                n.hi = glm::max(n.hi, v);
            }
        if (end - begin <= kLeafSize) {
            n.first = begin;
            n.count = end - begin;
            _nodes[index] = n;
            return;
        }
        const glm::dvec3 size = n.hi - n.lo;
        const int axis = size.x >= size.y && size.x >= size.z ? 0 : (size.y >= size.z ? 1 : 2);
        const int mid = (begin + end) / 2;
        std::nth_element(order.begin() + begin, order.begin() + mid, order.begin() + end,
                         [&](int x, int y) { return centre(x)[axis] < centre(y)[axis]; });
        n.first = static_cast<int>(_nodes.size());
        _nodes[index] = n;
        _nodes.push_back({});
        _nodes.push_back({});
        build(order, begin, mid, n.first);
        build(order, mid, end, n.first + 1);
    }

    std::vector<Triangle> _triangles;
    std::vector<Node> _nodes;
};

std::vector<Triangle> trianglesOf(const Mesh& mesh, std::span<const std::uint32_t> indices) {
    std::vector<Triangle> out;
    out.reserve(indices.size() / 3);
    for (std::size_t k = 0; k + 2 < indices.size(); k += 3)
        out.push_back({glm::dvec3(mesh.positions[indices[k]]), glm::dvec3(mesh.positions[indices[k + 1]]),
                       glm::dvec3(mesh.positions[indices[k + 2]])});
    return out;
}

// The largest distance from samples of `from` to the surface of `to`.
double oneSided(const std::vector<Triangle>& from, const TriangleTree& to, int density) {
    const int steps = 2 * density;
    double worst = 0.0;
    int hint = -1;
    for (const Triangle& t : from) {
        worst = std::max(worst, to.distance((t.a + t.b + t.c) / 3.0, hint, worst));
        for (int i = 0; i <= steps; ++i)
            for (int j = 0; i + j <= steps; ++j) {
                const double u = static_cast<double>(i) / steps, v = static_cast<double>(j) / steps;
                worst = std::max(worst, to.distance(t.a + u * (t.b - t.a) + v * (t.c - t.a), hint, worst));
            }
    }
    return worst;
}

}  // namespace

double sampledHausdorffDistance(const Mesh& mesh, std::span<const std::uint32_t> a, std::span<const std::uint32_t> b,
                                int density) {
    if (a.size() < 3 || b.size() < 3 || density < 1) return 0.0;
    std::vector<Triangle> ta = trianglesOf(mesh, a), tb = trianglesOf(mesh, b);
    const TriangleTree treeA(ta), treeB(tb);
    return std::max(oneSided(ta, treeB, density), oneSided(tb, treeA, density));
}

std::vector<double> sampledHausdorffDistances(const Mesh& mesh, std::span<const std::uint32_t> a,
                                              const std::vector<std::span<const std::uint32_t>>& levels) {
    std::vector<double> out(levels.size(), 0.0);
    if (a.size() < 3) return out;
    const TriangleTree treeA(trianglesOf(mesh, a));
    std::vector<bool> inA(mesh.positions.size(), false), seen(mesh.positions.size(), false);
    for (std::uint32_t v : a) inA[v] = true;
    // Every vertex once (b's that are also a's lie on a: distance 0), every edge once (from the
    // triangle that lists it ascending: a closed mesh lists each edge once each way), every
    // centroid.
    auto sample = [&](std::span<const std::uint32_t> from, const TriangleTree& to, bool skipA, double& worst) {
        std::fill(seen.begin(), seen.end(), false);
        int hint = -1;
        for (std::size_t k = 0; k + 2 < from.size(); k += 3) {
            const glm::dvec3 p[3] = {glm::dvec3(mesh.positions[from[k]]), glm::dvec3(mesh.positions[from[k + 1]]),
                                     glm::dvec3(mesh.positions[from[k + 2]])};
            for (int c = 0; c < 3; ++c) {
                const std::uint32_t v = from[k + c], next = from[k + (c + 1) % 3];
                if (!seen[v] && !(skipA && inA[v])) worst = std::max(worst, to.distance(p[c], hint, worst));
                seen[v] = true;
                if (v < next) worst = std::max(worst, to.distance(0.5 * (p[c] + p[(c + 1) % 3]), hint, worst));
            }
            worst = std::max(worst, to.distance((p[0] + p[1] + p[2]) / 3.0, hint, worst));
        }
    };
    for (std::size_t l = 0; l < levels.size(); ++l) {
        if (levels[l].size() < 3) continue;
        const TriangleTree treeB(trianglesOf(mesh, levels[l]));
        sample(a, treeB, false, out[l]);
        sample(levels[l], treeA, true, out[l]);
    }
    return out;
}

double sampledHausdorffDistance(const Mesh& mesh, std::span<const std::uint32_t> a, std::span<const std::uint32_t> b) {
    if (b.size() < 3) return 0.0;
    return sampledHausdorffDistances(mesh, a, {b}).front();
}

}  // namespace cavewall::scenes
