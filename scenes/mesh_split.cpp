#include "scenes/mesh_split.h"

#include "config/error.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace cavewall::scenes {

namespace {

// The mesh of the triangles `triangles` of `m` (indices into its triangle list, ascending).
Mesh chunkOf(const Mesh& m, const std::vector<std::uint32_t>& triangles, const std::string& name) {
    Mesh c;
    c.name = name;
    c.material = m.material;
    std::vector<std::uint32_t> remap(m.positions.size(), UINT32_MAX);
    c.indices.reserve(triangles.size() * 3);
    for (std::uint32_t t : triangles)
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m.indices[3 * t + k];
            if (remap[v] == UINT32_MAX) {
                remap[v] = static_cast<std::uint32_t>(c.positions.size());
                c.positions.push_back(m.positions[v]);
                if (!m.normals.empty()) c.normals.push_back(m.normals[v]);
                if (!m.texCoords0.empty()) c.texCoords0.push_back(m.texCoords0[v]);
                if (!m.texCoords1.empty()) c.texCoords1.push_back(m.texCoords1[v]);
                if (!m.colors.empty()) c.colors.push_back(m.colors[v]);
                c.bounds.add(glm::dvec3(m.positions[v]));
            }
            c.indices.push_back(remap[v]);
        }
    return c;
}

}  // namespace

SplitStats splitLargeObjects(Scene& scene, std::size_t first, std::size_t end, double chunkMetres,
                             std::size_t minTriangles, Role role) {
    if (!std::isfinite(chunkMetres) || chunkMetres <= 0.0)
        throw Error("mesh split: chunk size: expected a finite number of metres > 0, got " +
                    std::to_string(chunkMetres));
    SplitStats stats;
    end = std::min(end, scene.objects.size());
    std::vector<Object> added;
    std::vector<int> cutMeshes;
    for (std::size_t i = first; i < end; ++i) {
        Object& o = scene.objects[i];
        if (o.role != role || o.mesh < 0 || static_cast<std::size_t>(o.mesh) >= scene.meshes.size()) continue;
        const glm::dvec3 size = o.worldBounds.size();
        if (std::max(size.x, size.z) <= chunkMetres) continue;
        const Mesh& m = scene.meshes[o.mesh];
        if (m.triangleCount() < minTriangles) continue;
        // Group the triangles by the column of their world centroid, in column order.
        std::map<std::pair<std::int64_t, std::int64_t>, std::vector<std::uint32_t>> groups;
        const double cap = static_cast<double>(INT32_MAX);
        for (std::size_t t = 0; t < m.triangleCount(); ++t) {
            glm::dvec3 c(0.0);
            for (int k = 0; k < 3; ++k) c += glm::dvec3(m.positions[m.indices[3 * t + k]]);
            const glm::dvec3 w = glm::dvec3(o.worldFromModel * glm::dvec4(c / 3.0, 1.0));
            auto column = [&](double v, double lo) {
                return static_cast<std::int64_t>(std::clamp(std::floor((v - lo) / chunkMetres), 0.0, cap));
            };
            groups[{column(w.x, o.worldBounds.min.x), column(w.z, o.worldBounds.min.z)}].push_back(
                static_cast<std::uint32_t>(t));
        }
        if (groups.size() < 2) continue;
        ++stats.objectsCut;
        const Object original = o;
        cutMeshes.push_back(original.mesh);
        bool firstGroup = true;
        for (const auto& [key, triangles] : groups) {
            const std::string name =
                original.name + " [chunk " + std::to_string(key.first) + "," + std::to_string(key.second) + "]";
            scene.meshes.push_back(chunkOf(scene.meshes[original.mesh], triangles, name));
            Object chunk = original;
            chunk.name = name;
            chunk.mesh = static_cast<int>(scene.meshes.size() - 1);
            chunk.worldBounds = scene.meshes.back().bounds.transformed(chunk.worldFromModel);
            ++stats.chunks;
            if (firstGroup) {
                scene.objects[i] = std::move(chunk);  // o is invalid from here
                firstGroup = false;
            } else {
                added.push_back(std::move(chunk));
            }
        }
    }
    if (stats.objectsCut == 0) return stats;
    // The chunks after the range's last object, so objects after it keep their order.
    scene.objects.insert(scene.objects.begin() + static_cast<std::ptrdiff_t>(end), added.begin(), added.end());
    // Drop the cut meshes no object uses any more, renumbering the rest (others stay, used or
    // not: only what this call made unused goes).
    std::vector<char> used(scene.meshes.size(), 1);
    for (int k : cutMeshes) used[k] = 0;
    for (const Object& o : scene.objects)
        if (o.mesh >= 0 && static_cast<std::size_t>(o.mesh) < used.size()) used[o.mesh] = 1;
    std::vector<int> renumber(scene.meshes.size(), -1);
    std::vector<Mesh> kept;
    for (std::size_t k = 0; k < scene.meshes.size(); ++k) {
        if (!used[k]) continue;
        renumber[k] = static_cast<int>(kept.size());
        kept.push_back(std::move(scene.meshes[k]));
    }
    scene.meshes = std::move(kept);
    for (Object& o : scene.objects)
        if (o.mesh >= 0 && static_cast<std::size_t>(o.mesh) < renumber.size()) o.mesh = renumber[o.mesh];
    return stats;
}

}  // namespace cavewall::scenes
