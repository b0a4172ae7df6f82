#include "app/scene_query.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::app {

namespace {

// Slab test: does the ray reach the box within maxDistance?
bool rayHitsBox(const glm::dvec3& origin, const glm::dvec3& direction, const scenes::Bounds& box, double maxDistance) {
    double t0 = 0.0, t1 = maxDistance;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(direction[i]) < 1e-15) {
            if (origin[i] < box.min[i] || origin[i] > box.max[i]) return false;
            continue;
        }
        double a = (box.min[i] - origin[i]) / direction[i], b = (box.max[i] - origin[i]) / direction[i];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
        if (t0 > t1) return false;
    }
    return true;
}

}  // namespace

std::optional<double> rayTriangle(const glm::dvec3& origin, const glm::dvec3& direction, const glm::dvec3& a,
                                  const glm::dvec3& b, const glm::dvec3& c) {
    const glm::dvec3 e1 = b - a, e2 = c - a, p = glm::cross(direction, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-14) return std::nullopt;
    const glm::dvec3 s = origin - a;
    const double u = glm::dot(s, p) / det;
    if (u < 0.0 || u > 1.0) return std::nullopt;
    const glm::dvec3 q = glm::cross(s, e1);
    const double v = glm::dot(direction, q) / det;
    if (v < 0.0 || u + v > 1.0) return std::nullopt;
    const double t = glm::dot(e2, q) / det;
    if (t < 0.0) return std::nullopt;
    return t;
}

SceneQuery::SceneQuery(const scenes::Scene& scene) {
    for (const scenes::Object& o : scene.objects) {
        if (o.role != scenes::Role::Structure) continue;
        const scenes::Mesh& mesh = scene.meshes[o.mesh];
        Group g{o.worldBounds, {}};
        for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
            std::array<glm::dvec3, 3> t;
            for (int k = 0; k < 3; ++k)
                t[k] = glm::dvec3(o.worldFromModel * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + k]]), 1.0));
            g.triangles.push_back(t);
        }
        if (!g.triangles.empty()) _groups.push_back(std::move(g));
    }
}

std::size_t SceneQuery::triangleCount() const {
    std::size_t n = 0;
    for (const Group& g : _groups) n += g.triangles.size();
    return n;
}

std::optional<double> SceneQuery::floorBelow(const glm::dvec3& point, double maxDrop) const {
    // A ray straight down; only surfaces whose normal points up count as floor.
    const glm::dvec3 down(0.0, -1.0, 0.0);
    std::optional<double> best;
    for (const Group& g : _groups) {
        if (!rayHitsBox(point, down, g.bounds, maxDrop)) continue;
        for (const auto& t : g.triangles) {
            const glm::dvec3 n = glm::cross(t[1] - t[0], t[2] - t[0]);
            if (std::abs(n.y) < 0.7 * glm::length(n)) continue;
            auto hit = rayTriangle(point, down, t[0], t[1], t[2]);
            if (hit && *hit <= maxDrop && (!best || point.y - *hit > *best)) best = point.y - *hit;
        }
    }
    return best;
}

std::optional<double> SceneQuery::castRay(const glm::dvec3& origin, const glm::dvec3& direction,
                                          double maxDistance) const {
    std::optional<double> best;
    for (const Group& g : _groups) {
        if (!rayHitsBox(origin, direction, g.bounds, best ? *best : maxDistance)) continue;
        for (const auto& t : g.triangles) {
            auto hit = rayTriangle(origin, direction, t[0], t[1], t[2]);
            if (hit && *hit <= maxDistance && (!best || *hit < *best)) best = hit;
        }
    }
    return best;
}

}  // namespace cavewall::app
