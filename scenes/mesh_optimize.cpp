#include "scenes/mesh_optimize.h"

#include "scenes/mesh_tools.h"

#include <meshoptimizer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <unordered_map>
#include <vector>

namespace cavewall::scenes {

namespace {

struct CellKey {
    std::int64_t x, y, z;
    bool operator==(const CellKey&) const = default;
};

struct CellHash {
    std::size_t operator()(const CellKey& k) const {
        return static_cast<std::size_t>(k.x * 73856093 ^ k.y * 19349663 ^ k.z * 83492791);
    }
};

double positionTolerance(const Mesh& mesh, double relative) {
    Bounds b;
    for (const glm::vec3& p : mesh.positions) b.add(glm::dvec3(p));
    if (b.empty()) return 0.0;
    const glm::dvec3 size = b.size();
    const double extent = std::max({size.x, size.y, size.z});
    const double magnitude = std::max({std::abs(b.min.x), std::abs(b.min.y), std::abs(b.min.z), std::abs(b.max.x),
                                       std::abs(b.max.y), std::abs(b.max.z)});
    const double ulp = magnitude * std::numeric_limits<float>::epsilon();
    return std::max({relative * extent, 4.0 * ulp, static_cast<double>(std::numeric_limits<float>::min())});
}

bool near(glm::vec3 a, glm::vec3 b, double tol) {
    return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

template <typename V>
bool sameWithin(const std::vector<V>& values, std::uint32_t a, std::uint32_t b, float tol) {
    if (values.empty()) return true;
    const V d = glm::abs(values[a] - values[b]);
    for (int c = 0; c < V::length(); ++c)
        if (d[c] > tol) return false;
    return true;
}

// Position twins: for every vertex, the first earlier vertex within `tol` (itself if none),
// found through a hash grid of cell size `tol` (a twin lies in one of the 27 cells around).
std::vector<std::uint32_t> positionTwins(const Mesh& mesh, double tol) {
    std::unordered_map<CellKey, std::vector<std::uint32_t>, CellHash> grid;
    std::vector<std::uint32_t> twin(mesh.positions.size());
    auto cellOf = [&](glm::vec3 p) {
        auto cell = [&](float c) { return static_cast<std::int64_t>(std::floor(c / tol)); };
        return CellKey{cell(p.x), cell(p.y), cell(p.z)};
    };
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const glm::vec3 p = mesh.positions[v];
        const CellKey c = cellOf(p);
        twin[v] = v;
        for (std::int64_t dx = -1; dx <= 1 && twin[v] == v; ++dx)
            for (std::int64_t dy = -1; dy <= 1 && twin[v] == v; ++dy)
                for (std::int64_t dz = -1; dz <= 1 && twin[v] == v; ++dz) {
                    auto it = grid.find({c.x + dx, c.y + dy, c.z + dz});
                    if (it == grid.end()) continue;
                    for (std::uint32_t r : it->second)
                        if (near(p, mesh.positions[r], tol)) {
                            twin[v] = r;
                            break;
                        }
                }
        if (twin[v] == v) grid[c].push_back(v);
    }
    return twin;
}

template <typename V>
void remapAttribute(std::vector<V>& values, const std::vector<std::uint32_t>& keep) {
    if (values.empty()) return;
    std::vector<V> out;
    out.reserve(keep.size());
    for (std::uint32_t v : keep) out.push_back(values[v]);
    values = std::move(out);
}

void keepVertices(Mesh& mesh, const std::vector<std::uint32_t>& keep) {
    remapAttribute(mesh.positions, keep);
    remapAttribute(mesh.normals, keep);
    remapAttribute(mesh.texCoords0, keep);
    remapAttribute(mesh.texCoords1, keep);
    remapAttribute(mesh.colors, keep);
}

// Vertices in first-use order; unused ones dropped.
void compactVertices(Mesh& mesh) {
    std::vector<std::uint32_t> remap(mesh.positions.size());
    const std::size_t used =
        meshopt_optimizeVertexFetchRemap(remap.data(), mesh.indices.data(), mesh.indices.size(), mesh.positions.size());
    std::vector<std::uint32_t> order(used);
    for (std::uint32_t v = 0; v < remap.size(); ++v)
        if (remap[v] != ~0u) order[remap[v]] = v;
    for (std::uint32_t& i : mesh.indices) i = remap[i];
    keepVertices(mesh, order);
}

}  // namespace

WeldResult weldVertices(Mesh& mesh, const WeldTolerance& tolerance) {
    WeldResult result;
    result.verticesBefore = mesh.positions.size();
    if (mesh.positions.empty()) return result;
    const double tol = positionTolerance(mesh, tolerance.relativePosition);
    const std::vector<std::uint32_t> twin = positionTwins(mesh, tol);
    // Per position representative, the welded vertices standing on it.
    std::unordered_map<std::uint32_t, std::vector<std::uint32_t>> onPosition;
    std::vector<std::uint32_t> weldedOf(mesh.positions.size()), keep;
    for (std::uint32_t v = 0; v < mesh.positions.size(); ++v) {
        const std::uint32_t rep = twin[v];
        if (mesh.positions[v] != mesh.positions[rep]) ++result.positionsSnapped;
        mesh.positions[v] = mesh.positions[rep];
        std::vector<std::uint32_t>& candidates = onPosition[rep];
        auto same = std::find_if(candidates.begin(), candidates.end(), [&](std::uint32_t k) {
            const std::uint32_t w = keep[k];
            return sameWithin(mesh.normals, v, w, tolerance.normal) &&
                   sameWithin(mesh.texCoords0, v, w, tolerance.texCoord) &&
                   sameWithin(mesh.texCoords1, v, w, tolerance.texCoord) &&
                   sameWithin(mesh.colors, v, w, tolerance.color);
        });
        if (same != candidates.end()) {
            weldedOf[v] = *same;
            continue;
        }
        weldedOf[v] = static_cast<std::uint32_t>(keep.size());
        candidates.push_back(weldedOf[v]);
        keep.push_back(v);
    }
    for (std::uint32_t& i : mesh.indices) i = weldedOf[i];
    keepVertices(mesh, keep);
    compactVertices(mesh);  // vertices no triangle uses (also before welding) go as well
    result.verticesAfter = mesh.positions.size();
    updateBounds(mesh);
    return result;
}

void optimizeVertexOrder(Mesh& mesh) {
    if (mesh.indices.empty()) return;
    std::vector<std::uint32_t> indices(mesh.indices.size());
    meshopt_optimizeVertexCache(indices.data(), mesh.indices.data(), mesh.indices.size(), mesh.positions.size());
    mesh.indices = std::move(indices);
    compactVertices(mesh);
}

double averageCacheMissRatio(const Mesh& mesh, unsigned cacheSize) {
    if (mesh.indices.empty()) return 0.0;
    return meshopt_analyzeVertexCache(mesh.indices.data(), mesh.indices.size(), mesh.positions.size(), cacheSize, 0, 0)
        .acmr;
}

}  // namespace cavewall::scenes
