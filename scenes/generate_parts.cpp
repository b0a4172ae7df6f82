#include "scenes/generate_parts.h"

#include "scenes/mesh_tools.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

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

void PartBuilder::cylinderY(glm::vec3 base, float radius, float height, glm::vec4 color) {
    appendMesh(mesh, makeCylinder(radius, height, std::max(6, 6 * detail), color), glm::translate(glm::mat4(1.0f), base));
}

void PartBuilder::cylinderAlong(int axis, glm::vec3 centre, float radius, float length, glm::vec4 color) {
    glm::mat4 m = glm::translate(glm::mat4(1.0f), centre);
    // makeCylinder runs along +Y from 0: turn +Y onto the axis, then centre it.
    if (axis == 0) m = glm::rotate(m, glm::radians(-90.0f), glm::vec3(0, 0, 1));
    if (axis == 2) m = glm::rotate(m, glm::radians(90.0f), glm::vec3(1, 0, 0));
    m = glm::translate(m, glm::vec3(0, -0.5f * length, 0));
    appendMesh(mesh, makeCylinder(radius, length, std::max(6, 6 * detail), color), m);
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
    PartBuilder b{{}, detail};
    const float len = 3.2f + 0.4f * static_cast<float>(variant), tall = 2.0f + 0.4f * static_cast<float>(variant);
    const glm::vec4 paint = variant == 1 ? kMachineGrey : kMachineGreen;
    b.box({0, 0.4f, 0}, {len + 0.6f, 0.8f, 2.0f}, kDark);                 // bed
    b.box({-0.3f, 0.8f + 0.5f * tall, 0}, {len, tall, 1.6f}, paint);       // enclosure
    b.box({0.5f * len + 0.1f, 1.4f, 0.9f}, {0.5f, 0.9f, 0.2f}, kDark);     // control panel
    b.cylinderY({0.2f, 0.8f, 0}, 0.35f, 0.25f, kSteel);                   // table
    b.cylinderY({0.2f, 1.9f, 0}, 0.12f, 0.9f, kSteel);                    // spindle
    b.cylinderAlong(0, {-0.5f * len, 1.4f, -0.6f}, 0.25f, 0.9f, kSteel);  // motor
    b.cylinderY({-0.5f * len + 0.3f, 0, 0.75f}, 0.3f, 1.0f, kBlue);       // coolant tank
    for (int i = 0; i < 6; ++i)  // bolts along the bed
        b.cylinderY({-0.5f * len + 0.3f + static_cast<float>(i) * len / 5.5f, 0.8f, -0.9f}, 0.05f, 0.08f, kSteel);
    return b.finish("machine-tool-" + std::to_string(variant));
}

// An industrial robot on a pedestal, about 2.2 m tall, footprint 1.2 m.
Mesh makeRobot(int detail) {
    PartBuilder b{{}, detail};
    b.cylinderY({0, 0, 0}, 0.45f, 0.4f, kDark);
    b.cylinderY({0, 0.4f, 0}, 0.35f, 0.5f, kOrange);
    b.cylinderAlong(2, {0, 1.0f, 0}, 0.22f, 0.6f, kOrange);    // shoulder
    b.box({0.25f, 1.45f, 0}, {0.25f, 0.9f, 0.25f}, kOrange);   // upper arm
    b.cylinderAlong(2, {0.25f, 1.9f, 0}, 0.16f, 0.45f, kOrange);
    b.box({0.7f, 1.95f, 0}, {0.9f, 0.18f, 0.18f}, kOrange);    // forearm
    b.cylinderAlong(0, {1.2f, 1.95f, 0}, 0.08f, 0.2f, kDark);  // wrist
    b.box({1.35f, 1.95f, 0.06f}, {0.1f, 0.12f, 0.04f}, kSteel);
    b.box({1.35f, 1.95f, -0.06f}, {0.1f, 0.12f, 0.04f}, kSteel);
    return b.finish("robot");
}

// A 3 m roller conveyor along x, 0.8 m wide, 0.9 m high.
Mesh makeConveyor(int detail) {
    PartBuilder b{{}, detail};
    for (float z : {-0.4f, 0.4f}) b.box({0, 0.85f, z}, {3.0f, 0.12f, 0.06f}, kYellow);
    for (float x : {-1.4f, 0.0f, 1.4f})
        for (float z : {-0.4f, 0.4f}) b.box({x, 0.4f, z}, {0.06f, 0.8f, 0.06f}, kDark);
    for (int i = 0; i < 14; ++i)
        b.cylinderAlong(2, {-1.4f + static_cast<float>(i) * 2.8f / 13.0f, 0.85f, 0}, 0.045f, 0.74f, kSteel);
    return b.finish("conveyor");
}

// An electrical cabinet, 1.2 m x 2 m x 0.6 m, back at z = -0.3.
Mesh makeCabinet(int detail) {
    PartBuilder b{{}, detail};
    b.box({0, 1.0f, 0}, {1.2f, 2.0f, 0.6f}, kWhite);
    b.box({0, 2.05f, 0}, {1.25f, 0.1f, 0.65f}, kDark);
    for (float x : {-0.3f, 0.3f}) {
        b.box({x, 1.0f, 0.31f}, {0.56f, 1.8f, 0.02f}, kMachineGrey);
        b.cylinderAlong(2, {x > 0 ? x - 0.22f : x + 0.22f, 1.1f, 0.34f}, 0.03f, 0.05f, kDark);
    }
    b.cylinderAlong(2, {0.3f, 1.7f, 0.34f}, 0.06f, 0.03f, kRed);  // warning lamp
    return b.finish("cabinet");
}

// An 8 m overhead pipe rack along x: posts to 6 m and four pipes with flanges every 2 m.
Mesh makePipeRack(int detail) {
    PartBuilder b{{}, detail};
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
    for (int i = 0; i < 3; ++i) b.cylinderAlong(0, {-0.6f + 0.6f * static_cast<float>(i), 0.55f, 0.05f}, 0.1f, 0.5f, kWhite);
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
    // Triangles are a + b * detail: measure at 1 and 2, solve, then step up if rounding fell short.
    std::vector<Mesh> one = kinds(1);
    const std::size_t t1 = drawn(one), t2 = drawn(kinds(2));
    if (t1 >= target || t2 <= t1) return one;
    int detail = static_cast<int>(std::min<std::size_t>(256, 1 + (target - t1 + (t2 - t1) - 1) / (t2 - t1)));
    std::vector<Mesh> meshes = kinds(detail);
    while (drawn(meshes) < target && detail < 256) meshes = kinds(++detail);
    return meshes;
}

}  // namespace cavewall::scenes
