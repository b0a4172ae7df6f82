#include "hierarchy/cluster_fades.h"

#include <algorithm>

namespace cavewall::hierarchy {

ClusterFades::ClusterFades(int frames) : _frames(frames) {}

namespace {

// This frame's cost of node n's box (ClusterFramePlan::boxMs, fill included), or its fixed part
// for a plan without them.
double fadedBoxMs(const ClusterModel& model, const ClusterFramePlan& plan, int node, ClusterRep rep) {
    const std::size_t n = static_cast<std::size_t>(node);
    if (n < plan.boxMs.size()) return plan.boxMs[n][rep == ClusterRep::Average ? 1 : 0];
    return boxCostMs(model.costs, rep, 0.0);
}

// A ghost object's cost: drawn at full detail.
double objectMs(const ClusterModel& model, int object) {
    return model.costs.msPerObject + static_cast<double>(model.objectTriangles.at(object)) * model.costs.msPerTriangle;
}

// Marks every ancestor of node n as refined, stopping at the first one already marked.
void markAncestors(const std::vector<int>& parent, std::vector<char>& refined, int n) {
    for (int p = parent[n]; p >= 0 && !refined[p]; p = parent[p]) refined[p] = 1;
}

// Sets the weight of node's opaque boxes in `boxes` to `weight`.
void weighBox(std::vector<ClusterBoxDraw>& boxes, int node, float weight) {
    for (ClusterBoxDraw& b : boxes)
        if (b.node == node && b.weight == 1.0f) b.weight = weight;
}

}  // namespace

bool ClusterFades::below(int m, int n) const {
    for (int p = _parent[m]; p >= 0; p = _parent[p])
        if (p == n) return true;
    return false;
}

// A new model: start over.
void ClusterFades::restart(const ClusterTree& tree) {
    const std::size_t count = tree.nodes.size();
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

// This frame's selection, as it came from the traversal.
ClusterFades::Selection ClusterFades::selectionOf(const ClusterFramePlan& plan) const {
    const std::size_t count = _parent.size();
    Selection now{std::vector<int>(count, -1), std::vector<char>(count, 0)};
    for (int o : plan.objects)
        if (o >= 0 && static_cast<std::size_t>(o) < count) markAncestors(_parent, now.refined, o);
    for (const ClusterBoxDraw& b : plan.boxes) {
        now.box[b.node] = static_cast<int>(b.rep);
        markAncestors(_parent, now.refined, b.node);
    }
    return now;
}

// Fades under way: one frame older; ended when done or when their switch was undone.
std::vector<ClusterFades::Fade> ClusterFades::continuedFades(const Selection& now) {
    std::vector<Fade> fades;
    for (Fade& f : _fades) {
        if (++f.age >= _frames) continue;
        const bool holds = f.kind == Kind::Refine ? now.box[f.node] < 0 && now.refined[f.node]
                                                  : now.box[f.node] == static_cast<int>(f.rep);
        if (holds) fades.push_back(std::move(f));
    }
    return fades;
}

// The fade of a switch of non-leaf node i since the last frame; nullopt: no switch.
std::optional<ClusterFades::Fade> ClusterFades::switchOf(const ClusterTree& tree, const Selection& now,
                                                         std::size_t i) const {
    if (tree.nodes[i].leaf()) return std::nullopt;
    const int n = static_cast<int>(i);
    const int was = _prevBox[i];
    const int box = now.box[i];
    Fade f;
    f.node = n;
    f.age = 1;
    if (was >= 0 && box < 0 && now.refined[i]) {
        f.kind = Kind::Refine;
        f.rep = static_cast<ClusterRep>(was);
    } else if (_prevRefined[i] && box >= 0) {
        f.kind = Kind::Coarsen;
        f.rep = static_cast<ClusterRep>(box);
        for (int o : _prevObjects)
            if (below(o, n)) f.ghostObjects.push_back(o);
        for (const ClusterBoxDraw& b : _prevBoxes)
            if (below(b.node, n)) f.ghostBoxes.push_back({b.node, b.rep, 1.0f});
    } else if (was >= 0 && box >= 0 && was != box) {
        f.kind = Kind::Swap;
        f.rep = static_cast<ClusterRep>(box);
        f.oldRep = static_cast<ClusterRep>(was);
    } else {
        return std::nullopt;
    }
    return f;
}

// New switches since the last frame, each replacing a fade of the same node.
void ClusterFades::addSwitches(const ClusterTree& tree, const Selection& now, std::vector<Fade>& fades) const {
    for (std::size_t i = 0; i < tree.nodes.size(); ++i) {
        std::optional<Fade> f = switchOf(tree, now, i);
        if (!f) continue;
        const int n = f->node;
        fades.erase(std::remove_if(fades.begin(), fades.end(), [&](const Fade& g) { return g.node == n; }),
                    fades.end());
        fades.push_back(std::move(*f));
    }
}

// Adds what the fades draw to `plan`; returns its extra cost in ms.
double ClusterFades::addFadeItems(const ClusterModel& model, const std::vector<Fade>& fades,
                                  ClusterFramePlan& plan) const {
    double extraMs = 0.0;
    for (const Fade& f : fades) {
        const float k = static_cast<float>(f.age) / static_cast<float>(_frames);
        switch (f.kind) {
            case Kind::Refine:
                plan.boxes.push_back({f.node, f.rep, 1.0f - k});
                extraMs += fadedBoxMs(model, plan, f.node, f.rep);
                break;
            case Kind::Coarsen:
                weighBox(plan.boxes, f.node, k);
                for (int o : f.ghostObjects) {
                    plan.objects.push_back(o);
                    extraMs += objectMs(model, o);
                }
                for (const ClusterBoxDraw& b : f.ghostBoxes) {
                    plan.boxes.push_back(b);
                    extraMs += fadedBoxMs(model, plan, b.node, b.rep);
                }
                plan.ghostObjects += static_cast<int>(f.ghostObjects.size());
                break;
            case Kind::Swap:
                weighBox(plan.boxes, f.node, k);
                plan.boxes.push_back({f.node, f.oldRep, 1.0f});
                extraMs += fadedBoxMs(model, plan, f.node, f.oldRep);
                break;
        }
    }
    return extraMs;
}

// Back to front, except that every box comes after the boxes below it and a weighted box after
// the opaque one of the same node: a stable topological order (both relations are acyclic, so
// some unplaced box always has nothing left to wait for).
void ClusterFades::orderBoxes(const ClusterTree& tree, glm::dvec3 eyeWorld, std::vector<ClusterBoxDraw>& boxes) const {
    auto distance = [&](const ClusterBoxDraw& b) { return glm::length(tree.nodes[b.node].bounds.centre() - eyeWorld); };
    std::stable_sort(boxes.begin(), boxes.end(),
                     [&](const ClusterBoxDraw& a, const ClusterBoxDraw& b) { return distance(a) > distance(b); });
    auto follows = [&](const ClusterBoxDraw& a, const ClusterBoxDraw& b) {  // a after b
        return below(b.node, a.node) || (a.node == b.node && a.weight < b.weight);
    };
    const std::size_t m = boxes.size();
    std::vector<int> pending(m, 0);  // boxes still to draw before box a
    for (std::size_t a = 0; a < m; ++a)
        for (std::size_t b = 0; b < m; ++b)
            if (a != b && follows(boxes[a], boxes[b])) ++pending[a];
    std::vector<char> placed(m, 0);
    std::vector<ClusterBoxDraw> ordered;
    ordered.reserve(m);
    for (std::size_t step = 0; step < m; ++step) {  // the farthest box that may go next
        std::size_t a = 0;
        while (placed[a] || pending[a] > 0) ++a;
        placed[a] = 1;
        ordered.push_back(boxes[a]);
        for (std::size_t c = 0; c < m; ++c)
            if (!placed[c] && follows(boxes[c], boxes[a])) --pending[c];
    }
    boxes = std::move(ordered);
}

void ClusterFades::apply(const ClusterModel& model, glm::dvec3 eyeWorld, ClusterFramePlan& plan) {
    if (_frames <= 1) return;
    const ClusterTree& tree = model.tree;
    if (_parent.size() != tree.nodes.size()) restart(tree);
    Selection now = selectionOf(plan);
    const std::vector<int> selectedObjects = plan.objects;
    const std::vector<ClusterBoxDraw> selectedBoxes = plan.boxes;

    std::vector<Fade> fades = continuedFades(now);
    if (!_first) addSwitches(tree, now, fades);
    const double extraMs = addFadeItems(model, fades, plan);
    plan.fades = static_cast<int>(fades.size());
    plan.predictedMs += extraMs;
    if (!fades.empty()) {
        std::sort(plan.objects.begin(), plan.objects.end());
        plan.objects.erase(std::unique(plan.objects.begin(), plan.objects.end()), plan.objects.end());
        orderBoxes(tree, eyeWorld, plan.boxes);
    }

    // Remembered for the next frame.
    _fades = std::move(fades);
    _prevBox.assign(tree.nodes.size(), -1);
    for (const ClusterBoxDraw& b : selectedBoxes) _prevBox[b.node] = static_cast<int>(b.rep);
    _prevRefined = std::move(now.refined);
    _prevObjects = selectedObjects;
    _prevBoxes = selectedBoxes;
    _first = false;
}

}  // namespace cavewall::hierarchy
