#include "app/start_pose.h"

#include "app/scene_query.h"
#include "render/view_all.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>
#include <vector>

namespace cavewall::app {
namespace {

constexpr int kGrid = 9;            // columns per side of the search grid
constexpr int kDirections = 16;     // horizontal rays from a candidate eye
constexpr double kMaxView = 100.0;  // m, the longest ray that counts for the facing
const double kUpCos = std::cos(glm::radians(25.0));

struct Hit {
    double t = 0.0;
    glm::dvec3 normal{0.0};  // world, unit, the face's front
};

// Slab test of a ray against a box within [0, maxT].
bool meetsBox(const glm::dvec3& o, const glm::dvec3& d, const scenes::Bounds& b, double maxT) {
    double t0 = 0.0, t1 = maxT;
    for (int i = 0; i < 3; ++i) {
        if (std::abs(d[i]) < 1e-15) {
            if (o[i] < b.min[i] || o[i] > b.max[i]) return false;
            continue;
        }
        double a = (b.min[i] - o[i]) / d[i], c = (b.max[i] - o[i]) / d[i];
        if (a > c) std::swap(a, c);
        t0 = std::max(t0, a);
        t1 = std::min(t1, c);
        if (t0 > t1) return false;
    }
    return true;
}

// Appends every face of `o` that the world ray meets within maxT.
void hitsOf(const scenes::Scene& scene, const scenes::Object& o, const glm::dvec3& origin, const glm::dvec3& dir,
            double maxT, std::vector<Hit>& out) {
    const scenes::Mesh& mesh = scene.meshes[o.mesh];
    const glm::dmat4& m = o.worldFromModel;
    for (std::size_t i = 0; i + 2 < mesh.indices.size(); i += 3) {
        std::array<glm::dvec3, 3> p;
        for (int k = 0; k < 3; ++k)
            p[k] = glm::dvec3(m * glm::dvec4(glm::dvec3(mesh.positions[mesh.indices[i + k]]), 1.0));
        const auto t = rayTriangle(origin, dir, p[0], p[1], p[2]);
        if (!t || *t > maxT) continue;
        glm::dvec3 n = glm::cross(p[1] - p[0], p[2] - p[0]);
        if (o.flipWinding) n = -n;  // a mirroring transform: front faces are clockwise
        const double len = glm::length(n);
        if (len > 0.0) out.push_back({*t, n / len});
    }
}

bool large(const scenes::Object& o, double minSide) {
    const glm::dvec3 s = o.worldBounds.size();
    return s.x >= minSide && s.z >= minSide;
}

// The lowest upward face in column (x, z) among the large objects, world y.
std::optional<double> lowestFloor(const scenes::Scene& scene, const scenes::Bounds& box, double x, double z,
                                  double minSide) {
    const glm::dvec3 origin(x, box.max.y + 1.0, z), down(0.0, -1.0, 0.0);
    const double maxT = box.size().y + 2.0;
    std::vector<Hit> hits;
    for (const scenes::Object& o : scene.objects)
        if (large(o, minSide) && meetsBox(origin, down, o.worldBounds, maxT))
            hitsOf(scene, o, origin, down, maxT, hits);
    std::optional<double> lowest;
    for (const Hit& h : hits)
        if (h.normal.y >= kUpCos && (!lowest || origin.y - h.t < *lowest)) lowest = origin.y - h.t;
    return lowest;
}

struct Look {
    bool insideSolid = true;
    double yaw = 0.0;  // the most open direction
};

// The 16 horizontal rays from `eye` through every object: inside a solid, and the facing.
Look lookAround(const scenes::Scene& scene, const glm::dvec3& eye) {
    int backs = 0;
    double longest = -1.0;
    Look look;
    for (int k = 0; k < kDirections; ++k) {
        const double yaw = 2.0 * M_PI * k / kDirections;
        const glm::dvec3 dir(-std::sin(yaw), 0.0, -std::cos(yaw));  // yaw 0 looks down -Z
        std::vector<Hit> hits;
        for (const scenes::Object& o : scene.objects)
            if (meetsBox(eye, dir, o.worldBounds, kMaxView)) hitsOf(scene, o, eye, dir, kMaxView, hits);
        const auto first =
            std::min_element(hits.begin(), hits.end(), [](const Hit& a, const Hit& b) { return a.t < b.t; });
        if (first != hits.end() && glm::dot(first->normal, dir) > 0.0) ++backs;
        const double free = first == hits.end() ? kMaxView : first->t;
        if (free > longest) {
            longest = free;
            look.yaw = yaw;
        }
    }
    look.insideSolid = backs > kDirections / 2;
    return look;
}

// Grid columns over the middle half of the box's floor plan, nearest the centre first.
std::vector<glm::dvec2> columns(const scenes::Bounds& box) {
    std::vector<glm::dvec2> out;
    const glm::dvec3 c = box.centre(), s = box.size();
    for (int i = 0; i < kGrid; ++i)
        for (int j = 0; j < kGrid; ++j)
            out.push_back({c.x + s.x * (i / (kGrid - 1.0) - 0.5) * 0.5, c.z + s.z * (j / (kGrid - 1.0) - 0.5) * 0.5});
    std::stable_sort(out.begin(), out.end(), [&](const glm::dvec2& a, const glm::dvec2& b) {
        return glm::distance(a, glm::dvec2(c.x, c.z)) < glm::distance(b, glm::dvec2(c.x, c.z));
    });
    return out;
}

}  // namespace

std::optional<StartPose> findFloorStart(const scenes::Scene& scene, double eyeHeight) {
    const scenes::Bounds box = scene.bounds();
    if (box.empty()) return std::nullopt;
    const double minSide = std::min(2.0, 0.25 * std::min(box.size().x, box.size().z));
    for (const glm::dvec2& column : columns(box)) {
        const std::optional<double> floor = lowestFloor(scene, box, column.x, column.y, minSide);
        if (!floor || *floor + eyeHeight >= box.max.y) continue;
        const glm::dvec3 eye(column.x, *floor + eyeHeight, column.y);
        const Look look = lookAround(scene, eye);
        if (look.insideSolid) continue;
        return StartPose{eye, look.yaw, true, *floor};
    }
    return std::nullopt;
}

StartPose startPose(const scenes::Scene& scene, const display::Display& display, double eyeHeight) {
    if (std::optional<StartPose> floor = findFloorStart(scene, eyeHeight)) return *floor;
    return viewAllPose(scene, display);
}

StartPose viewAllPose(const scenes::Scene& scene, const display::Display& display) {
    const display::HeadPose head = display.defaultHead();
    const render::ViewAll all = render::viewAll(display, head, scene.bounds());
    return StartPose{glm::dvec3(all.worldFromCave * glm::dvec4(head.position, 1.0)), 0.0, false, 0.0};
}

}  // namespace cavewall::app
