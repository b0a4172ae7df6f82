#include "scenes/mesh_tools.h"

#include <cmath>

namespace cavewall::scenes {

std::vector<std::uint32_t> stripToList(const std::vector<std::uint32_t>& indices) {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 0; i + 2 < indices.size(); ++i) {
        // glTF: triangle i is (i, i+1, i+2) for even i and (i, i+2, i+1) for odd i.
        const bool odd = i % 2 == 1;
        out.insert(out.end(), {indices[i], indices[odd ? i + 2 : i + 1], indices[odd ? i + 1 : i + 2]});
    }
    return out;
}

std::vector<std::uint32_t> fanToList(const std::vector<std::uint32_t>& indices) {
    std::vector<std::uint32_t> out;
    for (std::size_t i = 1; i + 1 < indices.size(); ++i)
        out.insert(out.end(), {indices[0], indices[i], indices[i + 1]});
    return out;
}

namespace {

// Twice the triangle's area as a vector along its normal, in double so that large but valid
// coordinates do not overflow and tiny ones do not vanish before the degeneracy test.
glm::dvec3 faceNormal(const Mesh& mesh, std::size_t t) {
    const glm::dvec3 a(mesh.positions[mesh.indices[3 * t]]);
    const glm::dvec3 b(mesh.positions[mesh.indices[3 * t + 1]]);
    const glm::dvec3 c(mesh.positions[mesh.indices[3 * t + 2]]);
    return glm::cross(b - a, c - a);
}

}  // namespace

bool isDegenerateTriangle(const Mesh& mesh, std::size_t t) {
    const std::uint32_t* i = &mesh.indices[3 * t];
    if (i[0] == i[1] || i[1] == i[2] || i[0] == i[2]) return true;
    const double len = glm::length(faceNormal(mesh, t));
    return !(len > 0.0) || !std::isfinite(len);
}

std::size_t countDegenerateTriangles(const Mesh& mesh) {
    std::size_t n = 0;
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) n += isDegenerateTriangle(mesh, t) ? 1 : 0;
    return n;
}

void generateNormals(Mesh& mesh) {
    std::vector<glm::dvec3> sum(mesh.positions.size(), glm::dvec3(0.0));
    for (std::size_t t = 0; t < mesh.triangleCount(); ++t) {
        if (isDegenerateTriangle(mesh, t)) continue;
        const glm::dvec3 n = faceNormal(mesh, t);
        for (int k = 0; k < 3; ++k) sum[mesh.indices[3 * t + k]] += n;
    }
    mesh.normals.resize(mesh.positions.size());
    for (std::size_t v = 0; v < sum.size(); ++v) {
        const double len = glm::length(sum[v]);
        // Opposite faces sharing a vertex can cancel exactly; fall back like an unused vertex.
        mesh.normals[v] = len > 0.0 && std::isfinite(len) ? glm::vec3(sum[v] / len) : glm::vec3(0, 1, 0);
    }
}

void updateBounds(Mesh& mesh) {
    mesh.bounds = {};
    for (const glm::vec3& p : mesh.positions) mesh.bounds.add(glm::dvec3(p));
}

}  // namespace cavewall::scenes
