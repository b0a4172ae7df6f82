#include "hierarchy/gl/cluster_costs.h"

#include "config/error.h"
#include "display/timing.h"
#include "scenes/image_io.h"
#include "walls/bake_key.h"
#include "walls/bake_manifest.h"
#include "walls/gl/offscreen_target.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <limits>
#include <numeric>

namespace cavewall::hierarchy::gl {

namespace {

constexpr int kRepetitions = 7;
constexpr double kMinTimedTriangles = 200000.0;
constexpr int kMaxRepeats = 64;
// 10^10 triangles a second: faster than any renderer, the floor of a slope too small to measure.
constexpr double kMinMsPerTriangle = 1e-7;

// The fastest of kRepetitions draws: other tenants of a shared machine only ever add time, and
// the controller (hierarchy/cluster_budget.h) measures what they add frame by frame.
double fastestMs(const std::function<void()>& draw) {
    double fastest = std::numeric_limits<double>::infinity();
    for (int i = 0; i < kRepetitions; ++i) {
        glFinish();
        const auto start = std::chrono::steady_clock::now();
        draw();
        glFinish();
        fastest = std::min(fastest,
                           std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
    }
    return fastest;
}

std::filesystem::path costFile(const scenes::Scene& scene, const std::string& rendererName,
                               const std::filesystem::path& cache, int resolution) {
    walls::KeyHasher h;
    h.text("cavewall cluster costs v4").text(rendererName).integer(resolution);
    for (std::uint64_t k : walls::objectKeys(scene)) h.integer(static_cast<std::int64_t>(k));
    return cache / "clusters" / ("costs-" + walls::hex64(h.value()) + ".json");
}

bool readCosts(const std::filesystem::path& file, hierarchy::ClusterCosts& costs) {
    try {
        std::ifstream in(file);
        if (!in) return false;
        const nlohmann::json j = nlohmann::json::parse(in);
        costs = {j.at("msPerTriangle").get<double>(),  j.at("msPerObject").get<double>(),
                 j.at("texturedBoxMs").get<double>(),  j.at("averageBoxMs").get<double>(),
                 j.at("texturedViewMs").get<double>(), j.at("averageViewMs").get<double>()};
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

}  // namespace

MeasuredCosts measureClusterCosts(render::gl::SceneRenderer& renderer, const ClusterImpostors& impostors,
                                  const hierarchy::ClusterModel& model, const scenes::Scene& scene,
                                  const std::string& rendererName, const std::filesystem::path& cache, int resolution) {
    if (resolution < 1 || resolution > 16384)
        throw Error("cluster costs: resolution: expected 1 to 16384 pixels, got " + std::to_string(resolution));
    MeasuredCosts result;
    result.file = costFile(scene, rendererName, cache, resolution);
    if (readCosts(result.file, result.costs)) {
        result.cached = true;
        return result;
    }
    const scenes::Bounds box =
        hierarchy::impostorBox(scene.bounds().empty() ? scenes::Bounds{{0, 0, 0}, {1, 1, 1}} : scene.bounds());
    const hierarchy::BoxView view = hierarchy::viewOfBox(box, glm::normalize(glm::dvec3(0.4, 0.6, 0.7)));
    const display::OffAxisFrustum frustum =
        display::offAxisFrustum(view.screen, view.eye, {0.05, std::numeric_limits<double>::infinity()});
    walls::gl::OffscreenTarget target{glm::ivec2(resolution)};
    render::gl::ViewTarget vt{target.framebuffer(), {0, 0, resolution, resolution}, glm::vec4(0.0f, 0.0f, 0.0f, 1.0f)};
    // One view of `objects`, drawn `times` times in one timed block and divided back: a small
    // scene's draws are far below the timer's and the machine's noise, so they repeat until a
    // set holds about kMinTimedTriangles.
    auto drawObjects = [&](const std::vector<int>& objects, int times) {
        render::DrawFilter filter;
        filter.objects = &objects;
        filter.frustumCull = false;
        return fastestMs([&] {
                   for (int i = 0; i < times; ++i) renderer.renderFrustum(frustum, glm::dmat4(1.0), vt, filter);
               }) /
               times;
    };
    // Objects by triangles: the smaller half and the larger half.
    std::vector<int> order(model.objectTriangles.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(),
                     [&](int a, int b) { return model.objectTriangles[a] < model.objectTriangles[b]; });
    const std::vector<int> small(order.begin(), order.begin() + order.size() / 2),
        large(order.begin() + order.size() / 2, order.end());
    auto triangles = [&](const std::vector<int>& set) {
        double t = 0.0;
        for (int o : set) t += static_cast<double>(model.objectTriangles[o]);
        return t;
    };
    const double gs = triangles(small), gl = triangles(large);
    const int times = static_cast<int>(std::clamp(std::ceil(kMinTimedTriangles / std::max(1.0, std::min(gs, gl))), 1.0,
                                                  static_cast<double>(kMaxRepeats)));
    const double empty = drawObjects({}, times);
    const double ts = std::max(0.0, drawObjects(small, times) - empty),
                 tl = std::max(0.0, drawObjects(large, times) - empty);
    const double ns = static_cast<double>(small.size()), nl = static_cast<double>(large.size());
    // ts = c ns + b gs, tl = c nl + b gl.
    const double det = ns * gl - nl * gs;
    double b = det != 0.0 ? (ns * tl - nl * ts) / det : -1.0;
    double c = det != 0.0 ? (ts * gl - tl * gs) / det : -1.0;
    if (!(b > 0.0 && c >= 0.0)) {
        b = (ts + tl) / std::max(1.0, gs + gl);
        c = 0.0;
    }
    // Still nothing measurable (a few boxes on an idle machine): the floor, so the selection never
    // takes geometry for free.
    b = std::max(b, kMinMsPerTriangle);
    result.costs.msPerTriangle = b;
    result.costs.msPerObject = c;
    // Boxes: every cluster's, then the root's alone, from the same view: two equations for the
    // fixed part of a box and its fill per whole view covered (viewShare).
    const glm::dmat4 clipFromWorld = frustum.clipFromFrame();
    std::vector<int> all;
    double shares = 0.0;
    for (std::size_t n = 0; n < model.tree.nodes.size(); ++n)
        if (n < model.hasImpostors.size() && model.hasImpostors[n]) {
            all.push_back(static_cast<int>(n));
            shares += hierarchy::viewShare(hierarchy::impostorBox(model.tree.nodes[n].bounds), clipFromWorld);
        }
    const int root = model.tree.root;
    const bool rootHasBox = root >= 0 && static_cast<std::size_t>(root) < model.hasImpostors.size() &&
                            model.hasImpostors[static_cast<std::size_t>(root)];
    const double rootShare =
        rootHasBox ? hierarchy::viewShare(hierarchy::impostorBox(model.tree.nodes[root].bounds), clipFromWorld) : 0.0;
    auto drawBoxes = [&](const std::vector<int>& nodes, hierarchy::ClusterRep rep) {
        std::vector<hierarchy::ClusterBoxDraw> boxes;
        for (int n : nodes) boxes.push_back({n, rep});
        return std::max(0.0, fastestMs([&] {
                                 const std::vector<int> none;
                                 render::DrawFilter filter;
                                 filter.objects = &none;
                                 renderer.renderFrustum(frustum, glm::dmat4(1.0), vt, filter);
                                 display::FrameStats stats;
                                 impostors.draw(boxes, view.eye, frustum, glm::dmat4(1.0), stats);
                             }) - empty);
    };
    for (hierarchy::ClusterRep rep : {hierarchy::ClusterRep::Textured, hierarchy::ClusterRep::Average}) {
        const double ta = all.empty() ? 0.0 : drawBoxes(all, rep), tb = rootHasBox ? drawBoxes({root}, rep) : 0.0;
        const hierarchy::BoxCost cost =
            hierarchy::solveBoxCost(static_cast<double>(all.size()), shares, ta, rootShare, tb);
        (rep == hierarchy::ClusterRep::Textured ? result.costs.texturedBoxMs : result.costs.averageBoxMs) =
            cost.fixedMs;
        (rep == hierarchy::ClusterRep::Textured ? result.costs.texturedViewMs : result.costs.averageViewMs) =
            cost.viewMs;
    }
    nlohmann::json j{{"renderer", rendererName},
                     {"resolution", resolution},
                     {"msPerTriangle", b},
                     {"msPerObject", c},
                     {"texturedBoxMs", result.costs.texturedBoxMs},
                     {"averageBoxMs", result.costs.averageBoxMs},
                     {"texturedViewMs", result.costs.texturedViewMs},
                     {"averageViewMs", result.costs.averageViewMs}};
    scenes::writeAtomically(result.file, [&](const std::filesystem::path& temporary) {
        std::ofstream out(temporary);
        out << j.dump(1) << "\n";
        out.close();
        if (!out) throw Error(temporary.string() + ": cannot write");
    });
    return result;
}

}  // namespace cavewall::hierarchy::gl
