#include "render/cluster_fades.h"

#include <algorithm>

namespace cavewall::render {

ClusterFades::ClusterFades(int frames) : _frames(frames) {}

namespace {

// This frame's cost of node n's box (ClusterFramePlan::boxMs, fill included), or its fixed part
// for a plan without them.
double fadedBoxMs(const ClusterModel& model, const ClusterFramePlan& plan, int node, ClusterRep rep) {
    const std::size_t n = static_cast<std::size_t>(node);
    if (n < plan.boxMs.size()) return plan.boxMs[n][rep == ClusterRep::Average ? 1 : 0];
    return boxCostMs(model.costs, rep, 0.0);
}

}  // namespace

void ClusterFades::apply(const ClusterModel& model, glm::dvec3 eyeWorld, ClusterFramePlan& plan) {
    if (_frames <= 1) return;
    const ClusterTree& tree = model.tree;
    const std::size_t count = tree.nodes.size();
    if (_parent.size() != count) {  // a new model: start over
        _parent.assign(count, -1);
        for (std::size_t n = 0; n < count; ++n)
            for (int c : tree.nodes[n].children) _parent[c] = static_cast<int>(n);
        _prevBox.assign(count, -1);
        _prevRefined.assign(count, 0);
        _prevObjects.clear();
        _prevBoxes.clear();
        _fades.clear();
        _first = true;
    }
    auto below = [&](int m, int n) {  // m strictly below n
        for (int p = _parent[m]; p >= 0; p = _parent[p])
            if (p == n) return true;
        return false;
    };

    // This frame's selection, as it came from the traversal.
    std::vector<int> box(count, -1);
    std::vector<char> refined(count, 0);
    auto markAncestors = [&](int n) {
        for (int p = _parent[n]; p >= 0 && !refined[p]; p = _parent[p]) refined[p] = 1;
    };
    for (int o : plan.objects)
        if (o >= 0 && static_cast<std::size_t>(o) < count) markAncestors(o);
    for (const ClusterBoxDraw& b : plan.boxes) {
        box[b.node] = static_cast<int>(b.rep);
        markAncestors(b.node);
    }
    const std::vector<int> selectedObjects = plan.objects;
    const std::vector<ClusterBoxDraw> selectedBoxes = plan.boxes;

    // Fades under way: one frame older; ended when done or when their switch was undone.
    std::vector<Fade> fades;
    for (Fade& f : _fades) {
        if (++f.age >= _frames) continue;
        const bool holds = f.kind == Kind::Refine ? box[f.node] < 0 && refined[f.node]
                                                  : box[f.node] == static_cast<int>(f.rep);
        if (holds) fades.push_back(std::move(f));
    }
    // New switches since the last frame.
    if (!_first) {
        for (std::size_t i = 0; i < count; ++i) {
            const int n = static_cast<int>(i);
            if (tree.nodes[i].leaf()) continue;
            const int was = _prevBox[i], now = box[i];
            Fade f;
            f.node = n;
            f.age = 1;
            if (was >= 0 && now < 0 && refined[i]) {
                f.kind = Kind::Refine;
                f.rep = static_cast<ClusterRep>(was);
            } else if (_prevRefined[i] && now >= 0) {
                f.kind = Kind::Coarsen;
                f.rep = static_cast<ClusterRep>(now);
                for (int o : _prevObjects)
                    if (below(o, n)) f.ghostObjects.push_back(o);
                for (const ClusterBoxDraw& b : _prevBoxes)
                    if (below(b.node, n)) f.ghostBoxes.push_back({b.node, b.rep, 1.0f});
            } else if (was >= 0 && now >= 0 && was != now) {
                f.kind = Kind::Swap;
                f.rep = static_cast<ClusterRep>(now);
                f.oldRep = static_cast<ClusterRep>(was);
            } else {
                continue;
            }
            fades.erase(std::remove_if(fades.begin(), fades.end(), [&](const Fade& g) { return g.node == n; }),
                        fades.end());
            fades.push_back(std::move(f));
        }
    }

    // What the fades add to the frame.
    double extraMs = 0.0;
    auto weightOf = [&](int node, float weight) {
        for (ClusterBoxDraw& b : plan.boxes)
            if (b.node == node && b.weight == 1.0f) b.weight = weight;
    };
    for (const Fade& f : fades) {
        const float k = static_cast<float>(f.age) / static_cast<float>(_frames);
        switch (f.kind) {
        case Kind::Refine:
            plan.boxes.push_back({f.node, f.rep, 1.0f - k});
            extraMs += fadedBoxMs(model, plan, f.node, f.rep);
            break;
        case Kind::Coarsen:
            weightOf(f.node, k);
            for (int o : f.ghostObjects) {
                plan.objects.push_back(o);
                extraMs += model.costs.msPerObject +
                           static_cast<double>(model.objectTriangles.at(o)) * model.costs.msPerTriangle;
            }
            for (const ClusterBoxDraw& b : f.ghostBoxes) {
                plan.boxes.push_back(b);
                extraMs += fadedBoxMs(model, plan, b.node, b.rep);
            }
            plan.ghostObjects += static_cast<int>(f.ghostObjects.size());
            break;
        case Kind::Swap:
            weightOf(f.node, k);
            plan.boxes.push_back({f.node, f.oldRep, 1.0f});
            extraMs += fadedBoxMs(model, plan, f.node, f.oldRep);
            break;
        }
    }
    plan.fades = static_cast<int>(fades.size());
    plan.predictedMs += extraMs;
    if (!fades.empty()) {
        std::sort(plan.objects.begin(), plan.objects.end());
        plan.objects.erase(std::unique(plan.objects.begin(), plan.objects.end()), plan.objects.end());
        // Back to front, except that every box comes after the boxes below it and a weighted box
        // after the opaque one of the same node: a stable topological order (both relations
        // are acyclic, so some unplaced box always has nothing left to wait for).
        auto distance = [&](const ClusterBoxDraw& b) { return glm::length(tree.nodes[b.node].bounds.centre() - eyeWorld); };
        std::stable_sort(plan.boxes.begin(), plan.boxes.end(),
                         [&](const ClusterBoxDraw& a, const ClusterBoxDraw& b) { return distance(a) > distance(b); });
        auto follows = [&](const ClusterBoxDraw& a, const ClusterBoxDraw& b) {  // a after b
            return below(b.node, a.node) || (a.node == b.node && a.weight < b.weight);
        };
        const std::size_t m = plan.boxes.size();
        std::vector<int> pending(m, 0);  // boxes still to draw before box a
        for (std::size_t a = 0; a < m; ++a)
            for (std::size_t b = 0; b < m; ++b)
                if (a != b && follows(plan.boxes[a], plan.boxes[b])) ++pending[a];
        std::vector<char> placed(m, 0);
        std::vector<ClusterBoxDraw> ordered;
        ordered.reserve(m);
        for (std::size_t step = 0; step < m; ++step) {  // the farthest box that may go next
            std::size_t a = 0;
            while (placed[a] || pending[a] > 0) ++a;
            placed[a] = 1;
            ordered.push_back(plan.boxes[a]);
            for (std::size_t c = 0; c < m; ++c)
                if (!placed[c] && follows(plan.boxes[c], plan.boxes[a])) --pending[c];
        }
        plan.boxes = std::move(ordered);
    }

    _fades = std::move(fades);
    _prevBox.assign(count, -1);
    for (const ClusterBoxDraw& b : selectedBoxes) _prevBox[b.node] = static_cast<int>(b.rep);
    _prevRefined = std::move(refined);
    _prevObjects = selectedObjects;
    _prevBoxes = selectedBoxes;
    _first = false;
}

}  // namespace cavewall::render
