#include "render/vertex_lighting.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace cavewall::render {

namespace {

// Whether the unit normal `n` lies within kFlatNormalSlack of `face` or of -face.
bool alongFace(const glm::vec3& n, const glm::dvec3& face) {
    const glm::dvec3 nd(n);
    return glm::length(nd - face) <= kFlatNormalSlack || glm::length(nd + face) <= kFlatNormalSlack;
}

}  // namespace

double flatMaxEdge(const scenes::Mesh& mesh, std::span<const std::uint32_t> indices) {
    const std::size_t vertices = mesh.positions.size();
    const bool hasNormals = mesh.normals.size() == vertices;
    const bool hasColors = !mesh.colors.empty();
    double longest = 0.0;
    for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
        const std::uint32_t i[3] = {indices[t], indices[t + 1], indices[t + 2]};
        if (i[0] >= vertices || i[1] >= vertices || i[2] >= vertices) return -1.0;
        if (hasColors && (i[0] >= mesh.colors.size() || i[1] >= mesh.colors.size() || i[2] >= mesh.colors.size()))
            return -1.0;
        const glm::dvec3 p0(mesh.positions[i[0]]), p1(mesh.positions[i[1]]), p2(mesh.positions[i[2]]);
        const glm::dvec3 cross = glm::cross(p1 - p0, p2 - p0);
        const double area2 = glm::length(cross);
        if (!(area2 > 0.0)) continue;  // degenerate: rasterises to nothing
        if (hasNormals) {
            const glm::dvec3 face = cross / area2;
            for (std::uint32_t v : i)
                if (!alongFace(mesh.normals[v], face)) return -1.0;
        }
        if (hasColors && (mesh.colors[i[0]] != mesh.colors[i[1]] || mesh.colors[i[0]] != mesh.colors[i[2]]))
            return -1.0;
        longest = std::max({longest, glm::length(p1 - p0), glm::length(p2 - p1), glm::length(p0 - p2)});
    }
    return longest;
}

double vertexLightingError(double edge, double distance) {
    if (!(distance > 0.0) || !std::isfinite(distance)) return std::numeric_limits<double>::infinity();
    const double r = edge / distance;
    return r * r / 6.0 + 2.0 * kFlatNormalSlack;
}

bool litPerVertex(double edge, double stretch, double distance, double tolerance) {
    if (!(tolerance > 0.0) || edge < 0.0 || !std::isfinite(stretch)) return false;
    return vertexLightingError(edge * stretch, distance) <= tolerance;
}

}  // namespace cavewall::render
