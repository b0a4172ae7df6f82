#include "hierarchy/cluster_tree.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <queue>

namespace cavewall::hierarchy {

namespace {

bool contains(const scenes::Bounds& outer, const scenes::Bounds& inner, double eps) {
    return glm::all(glm::greaterThanEqual(inner.min, outer.min - eps)) &&
           glm::all(glm::lessThanEqual(inner.max, outer.max + eps));
}

// Cells per axis at grid level `level` (0: the finest): the finest count halved, rounded up.
glm::ivec3 cellsAt(glm::ivec3 divisions, int level) {
    glm::ivec3 n;
    for (int a = 0; a < 3; ++a) n[a] = (divisions[a] + (1 << level) - 1) >> level;
    return n;
}

}  // namespace

ClusterTree buildClusterTree(const std::vector<scenes::Bounds>& objectBounds, glm::ivec3 divisions) {
    ClusterTree tree;
    tree.divisions = glm::max(divisions, glm::ivec3(1));
    scenes::Bounds model;
    std::vector<int> list;  // the child list: node indices not yet clustered
    for (std::size_t i = 0; i < objectBounds.size(); ++i) {
        ClusterNode leaf;
        leaf.bounds = objectBounds[i];
        leaf.object = static_cast<int>(i);
        leaf.objects = {static_cast<int>(i)};
        tree.nodes.push_back(leaf);
        if (objectBounds[i].empty()) continue;
        model.add(objectBounds[i]);
        list.push_back(static_cast<int>(i));
    }
    if (list.empty()) return tree;
    const glm::dvec3 size = model.size();
    const double eps = 1e-9 * std::max({size.x, size.y, size.z, 1.0});
    const glm::dvec3 base = size / glm::dvec3(tree.divisions);
    for (int level = 0;; ++level) {
        const glm::ivec3 cells = cellsAt(tree.divisions, level);
        const double span = static_cast<double>(1 << level);
        // Each entry goes to the cell holding its centre, if that cell contains it whole.
        std::map<long, std::vector<int>> inCell;  // ordered: deterministic cluster order
        for (int node : list) {
            const scenes::Bounds& b = tree.nodes[node].bounds;
            glm::ivec3 c;
            scenes::Bounds cell;
            for (int a = 0; a < 3; ++a) {
                const double width = base[a] * span;
                c[a] = width > 0.0 ? std::clamp(static_cast<int>(std::floor((b.centre()[a] - model.min[a]) / width)), 0,
                                                cells[a] - 1)
                                   : 0;
                cell.min[a] = model.min[a] + c[a] * width;
                // The last cell ends exactly at the model's bounds (no rounding left outside).
                cell.max[a] = c[a] == cells[a] - 1 ? model.max[a] : model.min[a] + (c[a] + 1) * width;
            }
            if (contains(cell, b, eps))
                inCell[(static_cast<long>(c.z) * cells.y + c.y) * cells.x + c.x].push_back(node);
        }
        std::vector<int> clustered;
        std::vector<int> added;
        for (auto& [key, members] : inCell) {
            if (members.size() < 2) continue;  // one entry: its impostors exist already
            std::sort(members.begin(), members.end());
            ClusterNode cluster;
            cluster.children = members;
            cluster.level = level + 1;
            for (int m : members) {
                cluster.bounds.add(tree.nodes[m].bounds);
                cluster.objects.insert(cluster.objects.end(), tree.nodes[m].objects.begin(),
                                       tree.nodes[m].objects.end());
            }
            std::sort(cluster.objects.begin(), cluster.objects.end());
            clustered.insert(clustered.end(), members.begin(), members.end());
            added.push_back(static_cast<int>(tree.nodes.size()));
            tree.nodes.push_back(std::move(cluster));
        }
        std::sort(clustered.begin(), clustered.end());
        std::vector<int> next;
        for (int node : list)
            if (!std::binary_search(clustered.begin(), clustered.end(), node)) next.push_back(node);
        next.insert(next.end(), added.begin(), added.end());
        list = std::move(next);
        if (cells == glm::ivec3(1)) break;  // the single top cell contains everything
    }
    // The top cell is the model's bounds, so it took every entry left: one remains.
    tree.root = list.front();
    return tree;
}

bool ClusterCoherence::allowRefine(int n) {
    if (n >= static_cast<int>(_counter.size())) {
        _counter.resize(n + 1, 0);
        _wanted.resize(n + 1, -2);
        _refined.resize(n + 1, -2);
    }
    if (_refined[n] == _frame - 1 || _refined[n] == _frame) {  // refined in the last frame: stays
        _refined[n] = _frame;
        return true;
    }
    _counter[n] = _wanted[n] == _frame - 1 ? _counter[n] + 1 : 1;
    _wanted[n] = _frame;
    if (_counter[n] <= _threshold) return false;
    _refined[n] = _frame;
    return true;
}

ClusterSelection selectClusters(const ClusterTree& tree, const std::vector<NodeFrame>& frame, double budgetMs,
                                ClusterCoherence* coherence) {
    ClusterSelection selection;
    const std::size_t count = tree.nodes.size();
    if (tree.root < 0 || frame.size() != count) return selection;
    // Pass 1: children come before their parents in tree.nodes, so one forward sweep is a
    // depth-first post-order.
    std::vector<double> benefit(count, 0.0), cost(count, 0.0), childrenCost(count, 0.0);
    std::vector<int> initial(count, -1);
    std::vector<std::uint8_t> visible(count, 0);
    for (std::size_t n = 0; n < count; ++n) {
        const ClusterNode& node = tree.nodes[n];
        if (node.leaf()) {
            benefit[n] = std::max(0.0, frame[n].benefit);
            visible[n] = frame[n].visible ? 1 : 0;
        } else {
            for (int c : node.children) {
                benefit[n] = std::max(benefit[n], benefit[c]);
                if (!visible[c]) continue;
                visible[n] = 1;
                childrenCost[n] += cost[c];
            }
        }
        const auto& reps = frame[n].representations;
        double best = -1.0;
        for (std::size_t r = 0; r < reps.size(); ++r) {
            const double ratio =
                reps[r].costMs > 0.0 ? reps[r].accuracy / reps[r].costMs : std::numeric_limits<double>::infinity();
            if (ratio > best) {
                best = ratio;
                initial[n] = static_cast<int>(r);
            }
        }
        if (initial[n] >= 0) cost[n] = std::max(0.0, reps[initial[n]].costMs);
    }
    if (coherence) coherence->beginFrame();
    if (!visible[tree.root]) return selection;
    // Pass 2: best first by benefit (ties: the lower node index, for determinism).
    auto lower = [&](int a, int b) { return benefit[a] != benefit[b] ? benefit[a] < benefit[b] : a > b; };
    std::priority_queue<int, std::vector<int>, decltype(lower)> open(lower);
    open.push(tree.root);
    double total = cost[tree.root];
    while (!open.empty()) {
        const int n = open.top();
        open.pop();
        const ClusterNode& node = tree.nodes[n];
        if (node.leaf()) {
            const auto& reps = frame[n].representations;
            if (initial[n] < 0) continue;
            int chosen = initial[n];
            for (std::size_t r = 0; r < reps.size(); ++r) {
                const double extra = std::max(0.0, reps[r].costMs) - cost[n];
                if (reps[r].accuracy > reps[chosen].accuracy && total + extra <= budgetMs + 1e-12)
                    chosen = static_cast<int>(r);
            }
            total += std::max(0.0, reps[chosen].costMs) - cost[n];
            selection.drawn.push_back({n, chosen});
            ++selection.leaves;
            continue;
        }
        const bool fits = total - cost[n] + childrenCost[n] <= budgetMs + 1e-12;
        // A cluster that shows nothing (no representation, or none with any accuracy: the eye
        // inside its box) is refined at once when it fits: delaying it would draw a hole; and
        // also over the budget when its children cost no more than it does (a box around the
        // eye fills every view): that only lowers the frame's cost.
        const bool useless = initial[n] < 0 || frame[n].representations[initial[n]].accuracy <= 0.0;
        const bool cheaper = useless && childrenCost[n] <= cost[n];
        if ((fits || cheaper) && (useless || !coherence || coherence->allowRefine(n))) {
            total += childrenCost[n] - cost[n];
            for (int c : node.children)
                if (visible[c]) open.push(c);
            continue;
        }
        if (initial[n] < 0) continue;
        selection.drawn.push_back({n, initial[n]});
        ++selection.clusters;
    }
    selection.costMs = 0.0;
    for (const ClusterChoice& c : selection.drawn)
        selection.costMs += std::max(0.0, frame[c.node].representations[c.representation].costMs);
    return selection;
}

}  // namespace cavewall::hierarchy
