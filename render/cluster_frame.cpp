#include "render/cluster_frame.h"

#include <algorithm>
#include <cmath>

namespace cavewall::render {

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
        f.representations.push_back({static_cast<int>(ClusterRep::Textured), model.costs.texturedBoxMs,
                                     eyeInside ? 0.0 : a.textured[direction]});
        f.representations.push_back({static_cast<int>(ClusterRep::Average), model.costs.averageBoxMs,
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

double controlledCostMs(const ClusterFramePlan& plan, double fullDetailMs) {
    if (plan.predictedMs >= plan.budgetMs) return plan.predictedMs;
    return std::max(plan.predictedMs, std::min(plan.budgetMs, fullDetailMs));
}

ClusterFramePlan planClusterFrame(const ClusterModel& model, const std::vector<display::ScreenView>& views,
                                  const glm::dmat4& worldFromCave, glm::dvec3 eyeWorld, double budgetMs,
                                  ClusterCoherence* coherence) {
    const std::vector<NodeFrame> frames = clusterNodeFrames(model, views, worldFromCave, eyeWorld);
    const ClusterSelection selection = selectClusters(model.tree, frames, budgetMs, coherence);
    ClusterFramePlan plan;
    plan.budgetMs = budgetMs;
    plan.predictedMs = selection.costMs;
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
    auto distance = [&](const ClusterBoxDraw& b) { return glm::length(model.tree.nodes[b.node].bounds.centre() - eyeWorld); };
    std::stable_sort(plan.boxes.begin(), plan.boxes.end(),
                     [&](const ClusterBoxDraw& a, const ClusterBoxDraw& b) { return distance(a) > distance(b); });
    return plan;
}

}  // namespace cavewall::render
