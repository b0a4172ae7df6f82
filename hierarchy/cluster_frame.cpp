#include "hierarchy/cluster_frame.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::hierarchy {

namespace {

// Whether `world` bounds may meet the view's frustum: not all eight corners outside one of the
// side planes or the near plane (reversed-Z: in front of the near plane is z > w). The far
// plane never culls (it may be infinite).
bool mayMeet(const scenes::Bounds& world, const glm::dmat4& clipFromWorld) {
    int outside[5] = {0, 0, 0, 0, 0};
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p((i & 1) ? world.max.x : world.min.x, (i & 2) ? world.max.y : world.min.y,
                           (i & 4) ? world.max.z : world.min.z);
        const glm::dvec4 c = clipFromWorld * glm::dvec4(p, 1.0);
        outside[0] += c.x < -c.w;
        outside[1] += c.x > c.w;
        outside[2] += c.y < -c.w;
        outside[3] += c.y > c.w;
        outside[4] += c.z > c.w;
    }
    return std::none_of(std::begin(outside), std::end(outside), [](int n) { return n == 8; });
}

bool inside(const scenes::Bounds& b, glm::dvec3 p) {
    return glm::all(glm::greaterThanEqual(p, b.min)) && glm::all(glm::lessThanEqual(p, b.max));
}

double benefitOf(const scenes::Bounds& b, glm::dvec3 eye) {
    const double r = 0.5 * glm::length(b.size());
    const double d = glm::length(eye - b.centre());
    return d <= r ? 1.0 : (r / d) * (r / d);
}

}  // namespace

double viewShare(const scenes::Bounds& world, const glm::dmat4& clipFromWorld) {
    if (world.empty()) return 0.0;
    glm::dvec2 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
    int behind = 0;
    for (int i = 0; i < 8; ++i) {
        const glm::dvec3 p((i & 1) ? world.max.x : world.min.x, (i & 2) ? world.max.y : world.min.y,
                           (i & 4) ? world.max.z : world.min.z);
        const glm::dvec4 c = clipFromWorld * glm::dvec4(p, 1.0);
        if (c.w <= 1e-9) {
            ++behind;
            continue;
        }
        lo = glm::min(lo, glm::dvec2(c) / c.w);
        hi = glm::max(hi, glm::dvec2(c) / c.w);
    }
    if (behind == 8) return 0.0;                     // all behind the eye
    if (!mayMeet(world, clipFromWorld)) return 0.0;  // beside the view
    if (behind > 0) return 1.0;                      // around the eye's plane: may fill the view
    lo = glm::clamp(lo, -1.0, 1.0);
    hi = glm::clamp(hi, -1.0, 1.0);
    return std::max(0.0, hi.x - lo.x) * std::max(0.0, hi.y - lo.y) / 4.0;
}

double boxCostMs(const ClusterCosts& costs, ClusterRep rep, double viewShares) {
    return rep == ClusterRep::Average ? costs.averageBoxMs + costs.averageViewMs * viewShares
                                      : costs.texturedBoxMs + costs.texturedViewMs * viewShares;
}

BoxCost solveBoxCost(double boxesA, double sharesA, double msA, double sharesB, double msB) {
    // msA = boxesA f + sharesA v, msB = f + sharesB v.
    const double det = sharesB * boxesA - sharesA;
    BoxCost c;
    if (boxesA > 0.0 && std::abs(det) > 1e-9) {
        c.viewMs = (boxesA * msB - msA) / det;
        c.fixedMs = msB - sharesB * c.viewMs;
    }
    if (!(c.viewMs >= 0.0 && c.fixedMs >= 0.0)) c = {boxesA > 0.0 ? msA / boxesA : 0.0, 0.0};
    c.fixedMs = std::max(c.fixedMs, 1e-6);
    return c;
}

std::vector<NodeFrame> clusterNodeFrames(const ClusterModel& model, const std::vector<display::ScreenView>& views,
                                         const glm::dmat4& worldFromCave, glm::dvec3 eyeWorld) {
    const ClusterTree& tree = model.tree;
    std::vector<NodeFrame> frames(tree.nodes.size());
    std::vector<glm::dmat4> clipFromWorld;
    const glm::dmat4 caveFromWorld = glm::inverse(worldFromCave);
    for (const display::ScreenView& v : views) clipFromWorld.push_back(v.frustum.clipFromFrame() * caveFromWorld);
    for (std::size_t n = 0; n < tree.nodes.size(); ++n) {
        const ClusterNode& node = tree.nodes[n];
        NodeFrame& f = frames[n];
        if (node.bounds.empty()) continue;
        if (node.leaf()) {
            f.benefit = benefitOf(node.bounds, eyeWorld);
            f.visible = std::any_of(clipFromWorld.begin(), clipFromWorld.end(),
                                    [&](const glm::dmat4& m) { return mayMeet(node.bounds, m); });
            const double triangles = static_cast<double>(model.objectTriangles.at(node.object));
            f.representations.push_back({static_cast<int>(ClusterRep::Full),
                                         model.costs.msPerObject + triangles * model.costs.msPerTriangle, 1.0});
            continue;
        }
        if (n >= model.hasImpostors.size() || !model.hasImpostors[n]) continue;
        const scenes::Bounds box = impostorBox(node.bounds);
        const bool eyeInside = inside(box, eyeWorld);
        const int direction = nearestAccuracyDirection(box, eyeWorld);
        const ClusterAccuracy& a = model.accuracy.at(n);
        double shares = 0.0;
        for (const glm::dmat4& m : clipFromWorld) shares += viewShare(box, m);
        f.representations.push_back({static_cast<int>(ClusterRep::Textured),
                                     boxCostMs(model.costs, ClusterRep::Textured, shares),
                                     eyeInside ? 0.0 : a.textured[direction]});
        f.representations.push_back({static_cast<int>(ClusterRep::Average),
                                     boxCostMs(model.costs, ClusterRep::Average, shares),
                                     eyeInside ? 0.0 : a.average[direction]});
    }
    return frames;
}

double fullDetailCostMs(const ClusterModel& model) {
    double ms = 0.0;
    for (const ClusterNode& node : model.tree.nodes)
        if (node.leaf() && !node.bounds.empty())
            ms += model.costs.msPerObject +
                  static_cast<double>(model.objectTriangles.at(node.object)) * model.costs.msPerTriangle;
    return ms;
}

ClusterFramePlan planClusterFrame(const ClusterModel& model, const std::vector<display::ScreenView>& views,
                                  const glm::dmat4& worldFromCave, glm::dvec3 eyeWorld, double budgetMs,
                                  ClusterCoherence* coherence) {
    const std::vector<NodeFrame> frames = clusterNodeFrames(model, views, worldFromCave, eyeWorld);
    const ClusterSelection selection = selectClusters(model.tree, frames, budgetMs, coherence);
    ClusterFramePlan plan;
    plan.budgetMs = budgetMs;
    plan.predictedMs = plan.selectedMs = selection.costMs;
    plan.cheapestMs = selectClusters(model.tree, frames, 0.0, nullptr).costMs;
    plan.boxMs.assign(frames.size(), {0.0, 0.0});
    for (std::size_t n = 0; n < frames.size(); ++n)
        for (const Representation& r : frames[n].representations)
            if (r.id == static_cast<int>(ClusterRep::Textured))
                plan.boxMs[n][0] = r.costMs;
            else if (r.id == static_cast<int>(ClusterRep::Average))
                plan.boxMs[n][1] = r.costMs;
    for (const ClusterChoice& c : selection.drawn) {
        const ClusterNode& node = model.tree.nodes[c.node];
        const auto rep = static_cast<ClusterRep>(frames[c.node].representations[c.representation].id);
        if (node.leaf()) {
            plan.objects.push_back(node.object);
            continue;
        }
        plan.boxes.push_back({c.node, rep});
        ++(rep == ClusterRep::Textured ? plan.textured : plan.average);
    }
    std::sort(plan.objects.begin(), plan.objects.end());
    auto distance = [&](const ClusterBoxDraw& b) {
        return glm::length(model.tree.nodes[b.node].bounds.centre() - eyeWorld);
    };
    std::stable_sort(plan.boxes.begin(), plan.boxes.end(),
                     [&](const ClusterBoxDraw& a, const ClusterBoxDraw& b) { return distance(a) > distance(b); });
    return plan;
}

}  // namespace cavewall::hierarchy
