#include "scenes/generate_parts.h"

#include "scenes/mesh_tools.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>

namespace cavewall::scenes {

std::uint64_t Rng::next() {
    std::uint64_t z = (_state += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

double Rng::uniform(double lo, double hi) {
    // 53 random bits -> [0, 1): exact in double, identical everywhere.
    return lo + (hi - lo) * static_cast<double>(next() >> 11) * 0x1.0p-53;
}

int Rng::below(int n) { return static_cast<int>(next() % static_cast<std::uint64_t>(n)); }

void PartBuilder::box(glm::vec3 centre, glm::vec3 size, glm::vec4 color) {
    appendMesh(mesh, makeBox(size, color), glm::translate(glm::mat4(1.0f), centre));
}

int PartBuilder::segments(float radius) const {
    const int refined = std::max(6, 6 * (cadLike ? std::min(detail, kFullTessellation) : detail));
    if (!cadLike || !(radius > kChordalDeviation)) return refined;
    // A regular n-gon inscribed in a circle of radius r deviates r (1 - cos(pi / n)) from it.
    const double n = std::ceil(3.14159265358979 / std::acos(1.0 - kChordalDeviation / radius));
    return std::max(6, std::min(refined, static_cast<int>(n)));
}

void PartBuilder::cylinderY(glm::vec3 base, float radius, float height, glm::vec4 color) {
    appendMesh(mesh, makeCylinder(radius, height, segments(radius), color), glm::translate(glm::mat4(1.0f), base));
}

void PartBuilder::cylinderAlong(int axis, glm::vec3 centre, float radius, float length, glm::vec4 color) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), centre);
    // makeCylinder runs along +Y from 0: turn +Y onto the axis, then centre it.
    if (axis == 0) m = glm::rotate(m, glm::radians(-90.0f), glm::vec3(0, 0, 1));
    if (axis == 2) m = glm::rotate(m, glm::radians(90.0f), glm::vec3(1, 0, 0));
    m = glm::translate(m, glm::vec3(0, -0.5f * length, 0));
    appendMesh(mesh, makeCylinder(radius, length, segments(radius), color), m);
}

Mesh PartBuilder::finish(std::string name) {
    mesh.name = std::move(name);
    mesh.texCoords0.clear();
    updateBounds(mesh);
    return std::move(mesh);
}

namespace {

const glm::vec4 kMachineGreen(0.35f, 0.55f, 0.45f, 1), kMachineGrey(0.62f, 0.64f, 0.66f, 1);
const glm::vec4 kSteel(0.5f, 0.52f, 0.55f, 1), kDark(0.18f, 0.19f, 0.2f, 1), kYellow(0.95f, 0.78f, 0.1f, 1);
const glm::vec4 kOrange(0.95f, 0.45f, 0.08f, 1), kRed(0.75f, 0.12f, 0.1f, 1), kBlue(0.15f, 0.3f, 0.7f, 1);
const glm::vec4 kWood(0.55f, 0.38f, 0.22f, 1), kFabric(0.3f, 0.4f, 0.55f, 1), kWhite(0.9f, 0.9f, 0.88f, 1);

}  // namespace

// Machine tools: 4 m x 2 m footprint along x (variant changes proportions), up to 2.8 m tall.
Mesh makeMachineTool(int variant, int detail) {
    PartBuilder b{{}, detail, true};
    const float len = 3.2f + 0.4f * static_cast<float>(variant), tall = 2.0f + 0.4f * static_cast<float>(variant);
    const glm::vec4 paint = variant == 1 ? kMachineGrey : kMachineGreen;
    b.box({0, 0.4f, 0}, {len + 0.6f, 0.8f, 2.0f}, kDark);                 // bed
    b.box({-0.3f, 0.8f + 0.5f * tall, 0}, {len, tall, 1.6f}, paint);      // enclosure
    b.box({0.5f * len + 0.1f, 1.4f, 0.9f}, {0.5f, 0.9f, 0.2f}, kDark);    // control panel
    b.cylinderY({0.2f, 0.8f, 0}, 0.35f, 0.25f, kSteel);                   // table
    b.cylinderY({0.2f, 1.9f, 0}, 0.12f, 0.9f, kSteel);                    // spindle
    b.cylinderAlong(0, {-0.5f * len, 1.4f, -0.6f}, 0.25f, 0.9f, kSteel);  // motor
    b.cylinderY({-0.5f * len + 0.3f, 0, 0.75f}, 0.3f, 1.0f, kBlue);       // coolant tank
    const int d = b.density();
    const int bolts = 6 + 6 * d;  // along the bed, front; and as many behind once there are sub-parts
    for (int i = 0; i < bolts; ++i) {
        const float x = -0.5f * len + 0.3f + static_cast<float>(i) * len / (static_cast<float>(bolts) - 0.5f);
        b.cylinderY({x, 0.8f, -0.9f}, 0.05f, 0.08f, kSteel);
        if (d > 0) b.cylinderY({x, 0.8f, 0.9f}, 0.04f, 0.06f, kSteel);
    }
    // Control panel buttons: a grid on the panel's front face (z = 1.0), 4 per row.
    for (int i = 0; i < 8 * d; ++i) {
        const float x = 0.5f * len - 0.05f + 0.1f * static_cast<float>(i % 4);
        const float y = 1.05f + 0.7f * static_cast<float>(i / 4) / static_cast<float>(2 * d);
        b.cylinderAlong(2, {x, y, 1.01f}, 0.018f, 0.02f, i % 3 == 0 ? kRed : (i % 3 == 1 ? kYellow : kMachineGreen));
    }
    // Tool magazine on the roof: a ring of holders around (-0.8, 0), radius 0.45.
    const float roof = 0.8f + tall;
    for (int i = 0; i < 12 * d; ++i) {
        const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(12 * d);
        b.cylinderY({-0.8f + 0.45f * std::cos(a), roof, 0.45f * std::sin(a)}, 0.025f, 0.15f, kSteel);
    }
    // Cable chain along the roof's back edge.
    for (int i = 0; i < 10 * d; ++i) {
        const float x = -1.5f + 2.5f * static_cast<float>(i) / static_cast<float>(10 * d);
        b.box({x, roof + 0.03f, 0.6f}, {0.07f, 0.05f, 0.08f}, kDark);
    }
    return b.finish("machine-tool-" + std::to_string(variant));
}

// An industrial robot on a pedestal, about 2.2 m tall, footprint 1.2 m.
Mesh makeRobot(int detail) {
    PartBuilder b{{}, detail, true};
    b.cylinderY({0, 0, 0}, 0.45f, 0.4f, kDark);
    b.cylinderY({0, 0.4f, 0}, 0.35f, 0.5f, kOrange);
    b.cylinderAlong(2, {0, 1.0f, 0}, 0.22f, 0.6f, kOrange);   // shoulder
    b.box({0.25f, 1.45f, 0}, {0.25f, 0.9f, 0.25f}, kOrange);  // upper arm
    b.cylinderAlong(2, {0.25f, 1.9f, 0}, 0.16f, 0.45f, kOrange);
    b.box({0.7f, 1.95f, 0}, {0.9f, 0.18f, 0.18f}, kOrange);    // forearm
    b.cylinderAlong(0, {1.2f, 1.95f, 0}, 0.08f, 0.2f, kDark);  // wrist
    b.box({1.35f, 1.95f, 0.06f}, {0.1f, 0.12f, 0.04f}, kSteel);
    b.box({1.35f, 1.95f, -0.06f}, {0.1f, 0.12f, 0.04f}, kSteel);
    const int d = b.density();
    for (int i = 0; i < 8 * d; ++i) {  // bolts round the pedestal
        const float a = 6.2831853f * static_cast<float>(i) / static_cast<float>(8 * d);
        b.cylinderY({0.4f * std::cos(a), 0.4f, 0.4f * std::sin(a)}, 0.02f, 0.03f, kSteel);
    }
    for (int i = 0; i < 8 * d; ++i) {  // cable harness up the upper arm and along the forearm
        const float t = static_cast<float>(i) / static_cast<float>(8 * d);
        if (t < 0.5f)
            b.cylinderY({0.25f, 1.0f + 1.8f * t, 0.16f}, 0.02f, 0.09f, kDark);
        else
            b.cylinderAlong(0, {0.25f + 1.8f * (t - 0.5f), 2.07f, 0.0f}, 0.02f, 0.09f, kDark);
    }
    return b.finish("robot");
}

// A 3 m roller conveyor along x, 0.8 m wide, 0.9 m high.
Mesh makeConveyor(int detail) {
    PartBuilder b{{}, detail, true};
    for (float z : {-0.4f, 0.4f}) b.box({0, 0.85f, z}, {3.0f, 0.12f, 0.06f}, kYellow);
    for (float x : {-1.4f, 0.0f, 1.4f})
        for (float z : {-0.4f, 0.4f}) b.box({x, 0.4f, z}, {0.06f, 0.8f, 0.06f}, kDark);
    // Rollers at a pitch that shrinks with the sub-parts, never overlapping.
    const int d = b.density(), rollers = 14 + 7 * d;
    const float pitch = 2.8f / static_cast<float>(rollers - 1), radius = std::min(0.045f, 0.45f * pitch);
    for (int i = 0; i < rollers; ++i)
        b.cylinderAlong(2, {-1.4f + static_cast<float>(i) * pitch, 0.85f, 0}, radius, 0.74f, kSteel);
    for (int i = 0; i < 6 * d; ++i) {  // bolts along both side rails
        const float x = -1.45f + 2.9f * static_cast<float>(i) / static_cast<float>(6 * d);
        for (float z : {-0.435f, 0.435f}) b.cylinderAlong(2, {x, 0.85f, z}, 0.012f, 0.01f, kDark);
    }
    return b.finish("conveyor");
}

// An electrical cabinet, 1.2 m x 2 m x 0.6 m, back at z = -0.3.
Mesh makeCabinet(int detail) {
    PartBuilder b{{}, detail, true};
    b.box({0, 1.0f, 0}, {1.2f, 2.0f, 0.6f}, kWhite);
    b.box({0, 2.05f, 0}, {1.25f, 0.1f, 0.65f}, kDark);
    for (float x : {-0.3f, 0.3f}) {
        b.box({x, 1.0f, 0.31f}, {0.56f, 1.8f, 0.02f}, kMachineGrey);
        b.cylinderAlong(2, {x > 0 ? x - 0.22f : x + 0.22f, 1.1f, 0.34f}, 0.03f, 0.05f, kDark);
    }
    b.cylinderAlong(2, {0.3f, 1.7f, 0.34f}, 0.06f, 0.03f, kRed);  // warning lamp
    const int d = b.density();
    for (int i = 0; i < 6 * d; ++i) {  // vent slats low on both doors
        const float y = 0.15f + 0.45f * static_cast<float>(i) / static_cast<float>(6 * d);
        for (float x : {-0.3f, 0.3f}) b.box({x, y, 0.325f}, {0.4f, 0.012f, 0.012f}, kDark);
    }
    for (int i = 0; i < 4 * d; ++i)  // cable glands on the roof
        b.cylinderY({-0.5f + static_cast<float>(i) / static_cast<float>(4 * d), 2.1f, -0.1f}, 0.02f, 0.04f, kDark);
    return b.finish("cabinet");
}

// An 8 m overhead pipe rack along x: posts to 6 m and four pipes with flanges every 2 m.
Mesh makePipeRack(int detail) {
    PartBuilder b{{}, detail, true};
    for (float x : {-3.8f, 3.8f}) {
        b.box({x, 3.0f, 0}, {0.25f, 6.0f, 0.25f}, kSteel);
        b.box({x, 5.2f, 0}, {0.2f, 0.2f, 1.4f}, kSteel);
    }
    const glm::vec4 colors[4] = {kRed, kBlue, kYellow, kMachineGreen};
    for (int p = 0; p < 4; ++p) {
        const float z = -0.5f + 0.33f * static_cast<float>(p), r = 0.08f + 0.04f * static_cast<float>(p % 2);
        b.cylinderAlong(0, {0, 5.4f + r, z}, r, 8.0f, colors[p]);
        for (int f = 0; f < 5; ++f)
            b.cylinderAlong(0, {-4.0f + 2.0f * static_cast<float>(f), 5.4f + r, z}, r * 1.4f, 0.06f, kSteel);
        // Per sub-part level: a valve (body, stem, handwheel) and a pair of flanges.
        const int d = b.density();
        for (int v = 0; v < d; ++v) {
            const float x = -3.5f + 7.0f * (static_cast<float>(v) + 0.5f) / static_cast<float>(d);
            b.box({x, 5.4f + r, z}, {0.2f, 2.2f * r, 2.2f * r}, kDark);
            b.cylinderY({x, 5.4f + 2.0f * r, z}, 0.012f, 0.18f, kSteel);
            b.cylinderY({x, 5.58f + 2.0f * r, z}, 0.1f, 0.02f, kRed);
            for (float dx : {-0.16f, 0.16f}) b.cylinderAlong(0, {x + dx, 5.4f + r, z}, r * 1.4f, 0.04f, kSteel);
        }
    }
    return b.finish("pipe-rack");
}

Mesh makeTable(int detail) {
    PartBuilder b{{}, detail};
    b.cylinderY({0, 0.72f, 0}, 0.6f, 0.04f, kWood);
    b.cylinderY({0, 0.0f, 0}, 0.06f, 0.72f, kWood);
    b.cylinderY({0, 0.0f, 0}, 0.3f, 0.03f, kWood);
    return b.finish("table");
}

Mesh makeChair(int detail) {
    PartBuilder b{{}, detail};
    b.box({0, 0.45f, 0}, {0.45f, 0.05f, 0.45f}, kWood);
    b.box({0, 0.75f, -0.2f}, {0.45f, 0.55f, 0.05f}, kWood);
    for (float x : {-0.2f, 0.2f})
        for (float z : {-0.2f, 0.2f}) b.cylinderY({x, 0, z}, 0.02f, 0.45f, kDark);
    return b.finish("chair");
}

Mesh makeSofa(int detail) {
    PartBuilder b{{}, detail};
    b.box({0, 0.25f, 0}, {1.8f, 0.4f, 0.8f}, kFabric);
    b.box({0, 0.6f, -0.3f}, {1.8f, 0.6f, 0.2f}, kFabric);
    for (float x : {-0.95f, 0.95f}) b.cylinderAlong(2, {x, 0.5f, 0}, 0.15f, 0.8f, kFabric);
    for (int i = 0; i < 3; ++i)
        b.cylinderAlong(0, {-0.6f + 0.6f * static_cast<float>(i), 0.55f, 0.05f}, 0.1f, 0.5f, kWhite);
    return b.finish("sofa");
}

Mesh makeBed(int detail) {
    PartBuilder b{{}, detail};
    b.box({0, 0.25f, 0}, {1.6f, 0.3f, 2.0f}, kWood);
    b.box({0, 0.48f, 0.05f}, {1.5f, 0.16f, 1.85f}, kWhite);
    b.box({0, 0.6f, -0.98f}, {1.6f, 0.9f, 0.06f}, kWood);
    for (float x : {-0.4f, 0.4f}) b.cylinderAlong(0, {x, 0.62f, -0.7f}, 0.1f, 0.6f, kWhite);
    return b.finish("bed");
}

Mesh makeShelf(int detail) {
    PartBuilder b{{}, detail};
    for (float x : {-0.5f, 0.5f}) b.box({x, 1.0f, 0}, {0.04f, 2.0f, 0.35f}, kWood);
    for (int i = 0; i < 5; ++i) b.box({0, 0.05f + 0.45f * static_cast<float>(i), 0}, {1.0f, 0.03f, 0.35f}, kWood);
    for (int i = 0; i < 4; ++i)  // jars on the shelves
        b.cylinderY({-0.3f + 0.2f * static_cast<float>(i), 0.52f + 0.45f * static_cast<float>(i % 3), 0}, 0.06f, 0.18f,
                    i % 2 ? kBlue : kRed);
    return b.finish("shelf");
}

Mesh makeLamp(int detail) {
    PartBuilder b{{}, detail};
    b.cylinderY({0, 0, 0}, 0.18f, 0.03f, kDark);
    b.cylinderY({0, 0.03f, 0}, 0.015f, 1.5f, kDark);
    b.cylinderY({0, 1.45f, 0}, 0.22f, 0.3f, kWhite);
    return b.finish("lamp");
}

std::vector<Mesh> meshesForTarget(const std::vector<Placement>& placements, std::size_t fixedTriangles,
                                  std::size_t target, const std::function<std::vector<Mesh>(int)>& kinds) {
    auto drawn = [&](const std::vector<Mesh>& meshes) {
        std::size_t n = fixedTriangles;
        for (const Placement& p : placements) n += meshes[p.kind].triangleCount();
        return n;
    };
    // Triangles grow with the detail: the smallest level that reaches the target, bracketed by
    // doubling (large levels are slow to build) and then bisected.
    int lo = 1, hi = 1;
    while (hi < 256 && drawn(kinds(hi)) < target) {
        lo = hi + 1;
        hi = std::min(256, 2 * hi);
    }
    while (lo < hi) {
        const int mid = (lo + hi) / 2;
        if (drawn(kinds(mid)) >= target)
            hi = mid;
        else
            lo = mid + 1;
    }
    return kinds(lo);
}

}  // namespace cavewall::scenes
