#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cmath>

namespace cavewall::scenes {

namespace {

void finish(Mesh& m) {
    m.bounds = {};
    for (const glm::vec3& p : m.positions) m.bounds.add(glm::dvec3(p));
}

// Appends one quad (two triangles) with a flat normal and colour.
void addQuad(Mesh& m, glm::vec3 o, glm::vec3 right, glm::vec3 up, glm::vec4 color) {
    const auto base = static_cast<std::uint32_t>(m.positions.size());
    const glm::vec3 n = glm::normalize(glm::cross(right, up));
    const glm::vec3 corners[4] = {o, o + right, o + right + up, o + up};
    const glm::vec2 uv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
    for (int i = 0; i < 4; ++i) {
        m.positions.push_back(corners[i]);
        m.normals.push_back(n);
        m.texCoords0.push_back(uv[i]);
        m.colors.push_back(color);
    }
    for (std::uint32_t i : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + i);
}

}  // namespace

Mesh makeBox(glm::vec3 size, glm::vec4 color) {
    Mesh m;
    m.name = "box";
    const glm::vec3 h = 0.5f * size;
    const glm::vec3 x(size.x, 0, 0), y(0, size.y, 0), z(0, 0, size.z);
    addQuad(m, {-h.x, -h.y, h.z}, x, y, color);   // +Z
    addQuad(m, {h.x, -h.y, -h.z}, -x, y, color);  // -Z
    addQuad(m, {h.x, -h.y, h.z}, -z, y, color);   // +X
    addQuad(m, {-h.x, -h.y, -h.z}, z, y, color);  // -X
    addQuad(m, {-h.x, h.y, h.z}, x, -z, color);   // +Y
    addQuad(m, {-h.x, -h.y, -h.z}, x, z, color);  // -Y
    finish(m);
    return m;
}

Mesh makeCylinder(float radius, float height, int segments, glm::vec4 color) {
    Mesh m;
    m.name = "cylinder";
    const float step = 2.0f * 3.14159265358979f / static_cast<float>(segments);
    for (int i = 0; i < segments; ++i) {
        const float a0 = step * static_cast<float>(i), a1 = a0 + step;
        const glm::vec3 p0(radius * std::cos(a0), 0, -radius * std::sin(a0));
        const glm::vec3 p1(radius * std::cos(a1), 0, -radius * std::sin(a1));
        const auto base = static_cast<std::uint32_t>(m.positions.size());
        // Side: smooth normals.
        for (glm::vec3 p : {p0, p1, p1 + glm::vec3(0, height, 0), p0 + glm::vec3(0, height, 0)}) {
            m.positions.push_back(p);
            m.normals.push_back(glm::normalize(glm::vec3(p.x, 0, p.z)));
            m.texCoords0.push_back({0, 0});
            m.colors.push_back(color);
        }
        for (std::uint32_t k : {0u, 1u, 2u, 0u, 2u, 3u}) m.indices.push_back(base + k);
        // Caps: fans around the axis.
        for (float y : {0.0f, height}) {
            const auto c = static_cast<std::uint32_t>(m.positions.size());
            const glm::vec3 n(0, y > 0 ? 1 : -1, 0);
            for (glm::vec3 p : {glm::vec3(0, y, 0), p0 + glm::vec3(0, y, 0), p1 + glm::vec3(0, y, 0)}) {
                m.positions.push_back(p);
                m.normals.push_back(n);
                m.texCoords0.push_back({0, 0});
                m.colors.push_back(color);
            }
            if (y > 0)
                m.indices.insert(m.indices.end(), {c, c + 1, c + 2});
            else
                m.indices.insert(m.indices.end(), {c, c + 2, c + 1});
        }
    }
    finish(m);
    return m;
}

Mesh makeTiledQuad(glm::vec3 origin, glm::vec3 right, glm::vec3 up, int tilesX, int tilesY, glm::vec4 a, glm::vec4 b) {
    Mesh m;
    m.name = "tiles";
    const glm::vec3 dx = right / static_cast<float>(tilesX), dy = up / static_cast<float>(tilesY);
    for (int j = 0; j < tilesY; ++j)
        for (int i = 0; i < tilesX; ++i)
            addQuad(m, origin + static_cast<float>(i) * dx + static_cast<float>(j) * dy, dx, dy, (i + j) % 2 ? b : a);
    finish(m);
    return m;
}

void appendMesh(Mesh& dst, const Mesh& src, const glm::mat4& m) {
    const auto base = static_cast<std::uint32_t>(dst.positions.size());
    const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(m)));
    for (std::size_t i = 0; i < src.positions.size(); ++i) {
        dst.positions.push_back(glm::vec3(m * glm::vec4(src.positions[i], 1.0f)));
        if (!src.normals.empty()) dst.normals.push_back(glm::normalize(normalMatrix * src.normals[i]));
        if (!src.texCoords0.empty()) dst.texCoords0.push_back(src.texCoords0[i]);
        if (!src.colors.empty()) dst.colors.push_back(src.colors[i]);
    }
    for (std::uint32_t i : src.indices) dst.indices.push_back(base + i);
    // The bounds grow by the appended positions only: recomputing them over all of `dst` on
    // every append made building a mesh of n parts O(n²) (generate plant --triangles 1e8).
    if (dst.bounds.empty() && base > 0) finish(dst);
    for (std::size_t i = base; i < dst.positions.size(); ++i) dst.bounds.add(glm::dvec3(dst.positions[i]));
}

Scene builtinTestScene() {
    Scene s;
    s.name = "builtin";
    const glm::vec4 light(0.85f, 0.85f, 0.82f, 1), dark(0.35f, 0.35f, 0.38f, 1);
    const glm::vec4 wallA(0.75f, 0.72f, 0.65f, 1), wallB(0.6f, 0.58f, 0.52f, 1);
    const float h = 5.0f, top = 3.0f;
    auto addStructure = [&](Mesh m, const char* name) {
        s.meshes.push_back(std::move(m));
        addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::dmat4(1.0), name, Role::Structure);
    };
    addStructure(makeTiledQuad({-h, 0, h}, {2 * h, 0, 0}, {0, 0, -2 * h}, 10, 10, light, dark), "floor");
    addStructure(makeTiledQuad({-h, top, -h}, {2 * h, 0, 0}, {0, 0, 2 * h}, 10, 10, wallA, wallB), "ceiling");
    addStructure(makeTiledQuad({-h, 0, -h}, {2 * h, 0, 0}, {0, top, 0}, 10, 3, wallA, wallB), "wall-north");
    addStructure(makeTiledQuad({h, 0, h}, {-2 * h, 0, 0}, {0, top, 0}, 10, 3, wallA, wallB), "wall-south");
    addStructure(makeTiledQuad({-h, 0, h}, {0, 0, -2 * h}, {0, top, 0}, 10, 3, wallA, wallB), "wall-west");
    addStructure(makeTiledQuad({h, 0, -h}, {0, 0, 2 * h}, {0, top, 0}, 10, 3, wallA, wallB), "wall-east");
    struct Box {
        glm::vec3 centre, size;
        glm::vec4 color;
        const char* name;
    };
    const Box boxes[] = {
        {{0.0f, 0.5f, -3.0f}, {1.0f, 1.0f, 1.0f}, {0.85f, 0.15f, 0.12f, 1}, "red"},
        {{-3.0f, 0.75f, -1.0f}, {0.8f, 1.5f, 0.8f}, {0.15f, 0.7f, 0.2f, 1}, "green"},
        {{3.0f, 0.4f, -1.5f}, {1.2f, 0.8f, 0.6f}, {0.15f, 0.3f, 0.85f, 1}, "blue"},
        {{-2.0f, 1.0f, -4.0f}, {0.6f, 2.0f, 0.6f}, {0.9f, 0.8f, 0.1f, 1}, "yellow"},
        {{2.5f, 0.3f, 3.0f}, {0.6f, 0.6f, 0.6f}, {0.8f, 0.2f, 0.8f, 1}, "magenta"},
    };
    for (const Box& b : boxes) {
        s.meshes.push_back(makeBox(b.size, b.color));
        addObject(s, static_cast<int>(s.meshes.size()) - 1, glm::translate(glm::dmat4(1.0), glm::dvec3(b.centre)),
                  b.name, Role::Content);
    }
    return s;
}

}  // namespace cavewall::scenes
