#include "scenes/facing_groups.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace cavewall::scenes {

namespace {

// 0..5: +x, -x, +y, -y, +z, -z by the normal's largest component; 0 for a zero normal.
int facingClass(const glm::dvec3& n) {
    const glm::dvec3 a = glm::abs(n);
    if (a.x >= a.y && a.x >= a.z) return n.x >= 0.0 ? 0 : 1;
    if (a.y >= a.z) return n.y >= 0.0 ? 2 : 3;
    return n.z >= 0.0 ? 4 : 5;
}

}  // namespace

std::size_t groupByFacing(Mesh& mesh, const FacingOptions& options) {
    mesh.facingGroups.clear();
    const std::size_t triangles = mesh.indices.size() / 3;
    if (triangles < std::max<std::size_t>(options.minTriangles, 1) || mesh.indices.size() % 3 != 0) return 0;
    for (std::uint32_t i : mesh.indices)
        if (i >= mesh.positions.size()) return 0;
    Bounds all;
    for (const glm::vec3& p : mesh.positions) all.add(glm::dvec3(p));
    const double perClass = static_cast<double>(triangles) / 6.0 / static_cast<double>(std::max<std::size_t>(options.trianglesPerGroup, 1));
    const int grid = std::clamp(static_cast<int>(std::cbrt(perClass)), 1, std::max(options.maxGridDivisions, 1));
    const glm::dvec3 size = glm::max(all.size(), glm::dvec3(1e-30));
    // Per triangle: its group key and its unit normal.
    std::vector<int> key(triangles);
    std::vector<glm::dvec3> normal(triangles);
    for (std::size_t t = 0; t < triangles; ++t) {
        const glm::dvec3 p0(mesh.positions[mesh.indices[3 * t]]), p1(mesh.positions[mesh.indices[3 * t + 1]]),
            p2(mesh.positions[mesh.indices[3 * t + 2]]);
        const glm::dvec3 c = glm::cross(p1 - p0, p2 - p0);
        const double length = glm::length(c);
        normal[t] = length > 0.0 ? c / length : glm::dvec3(0.0);
        const glm::ivec3 g = glm::clamp(glm::ivec3(glm::floor((((p0 + p1 + p2) / 3.0) - all.min) / size * double(grid))),
                                        glm::ivec3(0), glm::ivec3(grid - 1));
        key[t] = ((facingClass(normal[t]) * grid + g.z) * grid + g.y) * grid + g.x;
    }
    std::vector<std::uint32_t> order(triangles);
    std::iota(order.begin(), order.end(), 0u);
    std::stable_sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) { return key[a] < key[b]; });
    std::vector<std::uint32_t> indices(mesh.indices.size());
    std::vector<FacingGroup> groups;
    for (std::size_t k = 0; k < triangles; ++k) {
        const std::uint32_t t = order[k];
        if (groups.empty() || key[order[k - 1]] != key[t]) {
            FacingGroup g;
            g.firstIndex = static_cast<std::uint32_t>(3 * k);
            groups.push_back(g);
        }
        FacingGroup& g = groups.back();
        g.indexCount += 3;
        g.axis += normal[t];
        for (int v = 0; v < 3; ++v) {
            indices[3 * k + v] = mesh.indices[3 * t + v];
            g.bounds.add(glm::dvec3(mesh.positions[mesh.indices[3 * t + v]]));
        }
    }
    mesh.indices = std::move(indices);
    // Axis: the mean normal; spread: the largest angle from it (degenerate triangles face
    // nowhere and draw nothing, so they do not widen it).
    for (FacingGroup& g : groups) {
        const double length = glm::length(g.axis);
        g.axis = length > 0.0 ? g.axis / length : glm::dvec3(0.0);
        double minCos = length > 0.0 ? 1.0 : -1.0;
        for (std::uint32_t i = g.firstIndex; i < g.firstIndex + g.indexCount; i += 3) {
            const glm::dvec3& n = normal[order[i / 3]];
            if (n != glm::dvec3(0.0)) minCos = std::min(minCos, glm::dot(n, g.axis));
        }
        g.sinSpread = minCos <= 0.0 ? 1.0 : std::sqrt(std::max(0.0, 1.0 - minCos * minCos));
    }
    mesh.facingGroups = std::move(groups);
    return mesh.facingGroups.size();
}

bool facingGroupsValid(const Mesh& mesh) {
    std::size_t next = 0;
    for (const FacingGroup& g : mesh.facingGroups) {
        if (g.firstIndex != next || g.indexCount == 0 || g.indexCount % 3 != 0) return false;
        next += g.indexCount;
    }
    return next == mesh.indices.size();
}

bool facesAway(const FacingGroup& group, const glm::dvec3& eyeModel) {
    if (group.bounds.empty() || !(group.sinSpread < 1.0)) return false;
    const glm::dvec3 c = group.bounds.centre(), h = 0.5 * group.bounds.size();
    const glm::dvec3 toCentre = c - eyeModel;
    const double nearest = glm::dot(group.axis, toCentre) - glm::dot(glm::abs(group.axis), h);
    const double farthest = glm::length(toCentre) + glm::length(h);
    // A relative margin for rounding: a triangle exactly edge-on is not culled.
    const double margin = 1e-9 * (farthest + glm::length(c));
    return nearest > farthest * group.sinSpread + margin;
}

}  // namespace cavewall::scenes
