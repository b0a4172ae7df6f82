// The generated production hall. Layout (top view, x right, z down; metres):
//
//   z=-20 +-------------+-------------+-------------+
//         |             |      B      |      D      |
//         |      A      |-------------+-------------|  z = 0: virtual walls B|C and D|E
//         |             |      C      |      E      |
//   z=+20 +-------------+-------------+-------------+
//        x=-40        x=-12         x=12          x=40
//
// Machine rows run along x at z = -16, -4, 4, 16 with aisles at z = -10 and 10 (the walk path)
// and cross aisles at x = -26 and 26; cabinets line the long walls, pipe racks run overhead
// along them, conveyors sit beside the rows next to z = 0, columns stand on z = 0.
#include "scenes/generate.h"
#include "scenes/generate_parts.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::scenes {
namespace {

constexpr double kHalfX = 40.0, kHalfZ = 20.0, kHeight = 8.0, kEye = 1.7;

enum Kind { Machine0, Machine1, Machine2, RobotKind, ConveyorKind, CabinetKind, RackKind, KindCount };

std::vector<Mesh> plantKinds(int detail) {
    return {makeMachineTool(0, detail), makeMachineTool(1, detail), makeMachineTool(2, detail), makeRobot(detail),
            makeConveyor(detail), makeCabinet(detail), makePipeRack(detail)};
}

glm::dmat4 place(double x, double z, double yawDeg) {
    return glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(x, 0, z)), glm::radians(yawDeg), glm::dvec3(0, 1, 0));
}

// Station x positions per cell column, clear of the virtual walls (x = +-12) and cross aisles.
const double kStationsA[] = {-36, -31, -21, -16};
const double kStationsBC[] = {-7, 0, 7};
const double kStationsDE[] = {16.5, 21.5, 31, 36};

void addStation(std::vector<Placement>& out, Rng& rng, double x, double rowZ, int& n) {
    const std::string id = std::to_string(n++);
    const bool facingAisle = std::abs(rowZ) > 10.0 ? rowZ < 0 : rowZ > 0;  // outer rows face inwards
    const double towardsAisle = (std::abs(rowZ) > 10.0) == (rowZ < 0) ? 1.0 : -1.0;
    out.push_back({Machine0 + rng.below(3), place(x, rowZ, facingAisle ? 0.0 : 180.0), "machine-" + id});
    if (rng.chance(0.6))  // robots stand between the machine and the aisle
        out.push_back({RobotKind, place(x + rng.uniform(-1.0, 1.0), rowZ + 2.6 * towardsAisle, rng.uniform(0, 360)),
                       "robot-" + id});
    if (std::abs(rowZ) < 10.0 && rng.chance(0.5))  // conveyors between the inner rows and z = 0
        out.push_back({ConveyorKind, place(x, rowZ > 0 ? 2.0 : -2.0, 0.0), "conveyor-" + id});
}

std::vector<Placement> plantContent(Rng& rng) {
    std::vector<Placement> out;
    int n = 0;
    for (double z : {-16.0, -4.0, 4.0, 16.0}) {
        for (double x : kStationsA) addStation(out, rng, x, z, n);
        for (double x : kStationsBC) addStation(out, rng, x, z, n);
        for (double x : kStationsDE) addStation(out, rng, x, z, n);
    }
    for (double side : {-1.0, 1.0}) {
        // Cabinets against the long walls, backs to the wall, clear of x = +-12 and the racks' posts.
        for (double x = -38.0; x <= 38.0; x += 3.0) {
            if (std::abs(std::abs(x) - 12.0) < 1.5 || !rng.chance(0.55)) continue;
            out.push_back({CabinetKind, place(x, side * (kHalfZ - 0.35), side < 0 ? 0.0 : 180.0),
                           "cabinet-" + std::to_string(n++)});
        }
        for (double x : {-35.5, -27.5, -19.5, -4.0, 4.0, 18.0, 26.0, 34.0})
            out.push_back({RackKind, place(x, side * 18.5, 0.0), "pipe-rack-" + std::to_string(n++)});
    }
    return out;
}

void addStructure(Scene& s, Mesh mesh, const std::vector<glm::dmat4>& where, const std::string& name) {
    s.meshes.push_back(std::move(mesh));
    for (std::size_t i = 0; i < where.size(); ++i)
        addObject(s, static_cast<int>(s.meshes.size()) - 1, where[i],
                  "structure/" + name + (where.size() > 1 ? "-" + std::to_string(i) : ""), Role::Structure);
}

void plantStructure(Scene& s) {
    const glm::vec4 floorA(0.55f, 0.56f, 0.55f, 1), floorB(0.48f, 0.49f, 0.5f, 1);
    const glm::vec4 wallA(0.78f, 0.76f, 0.7f, 1), wallB(0.72f, 0.7f, 0.64f, 1), roof(0.6f, 0.62f, 0.66f, 1);
    const float hx = static_cast<float>(kHalfX), hz = static_cast<float>(kHalfZ), h = static_cast<float>(kHeight);
    const glm::dmat4 id(1.0);
    addStructure(s, makeTiledQuad({-hx, 0, hz}, {2 * hx, 0, 0}, {0, 0, -2 * hz}, 40, 20, floorA, floorB), {id}, "floor");
    addStructure(s, makeTiledQuad({-hx, h, -hz}, {2 * hx, 0, 0}, {0, 0, 2 * hz}, 10, 5, roof, roof), {id}, "roof");
    addStructure(s, makeTiledQuad({-hx, 0, -hz}, {2 * hx, 0, 0}, {0, h, 0}, 20, 2, wallA, wallB), {id}, "wall-north");
    addStructure(s, makeTiledQuad({hx, 0, hz}, {-2 * hx, 0, 0}, {0, h, 0}, 20, 2, wallA, wallB), {id}, "wall-south");
    addStructure(s, makeTiledQuad({-hx, 0, hz}, {0, 0, -2 * hz}, {0, h, 0}, 10, 2, wallA, wallB), {id}, "wall-west");
    addStructure(s, makeTiledQuad({hx, 0, -hz}, {0, 0, 2 * hz}, {0, h, 0}, 10, 2, wallA, wallB), {id}, "wall-east");
    std::vector<glm::dmat4> columns, beams;
    for (double x : {-34.0, -18.0, -4.0, 4.0, 18.0, 34.0})
        columns.push_back(glm::translate(id, glm::dvec3(x, 0.5 * kHeight, 0)));
    addStructure(s, makeBox({0.5f, h, 0.5f}, {0.7f, 0.7f, 0.72f, 1}), columns, "column");
    for (double x = -36.0; x <= 36.0; x += 8.0) beams.push_back(glm::translate(id, glm::dvec3(x, kHeight - 0.35, 0)));
    addStructure(s, makeBox({0.3f, 0.7f, 2 * hz}, {0.45f, 0.47f, 0.5f, 1}), beams, "beam");
}

// Cell regions counter-clockwise seen from above (from +x towards -z).
std::vector<glm::dvec2> rect(double x0, double x1, double z0, double z1) {
    return {{x0, z1}, {x1, z1}, {x1, z0}, {x0, z0}};
}

// A full-height virtual wall on the floor segment p0 -> p1 whose front faces `front`'s side.
VirtualWall wall(const std::string& name, glm::dvec2 p0, glm::dvec2 p1, int front, int back, glm::dvec2 frontPoint) {
    const glm::dvec3 a(p0.x, 0, p0.y), b(p1.x, 0, p1.y);
    const glm::dvec3 normal = glm::cross(b - a, glm::dvec3(0, 1, 0));
    const bool faces = glm::dot(normal, glm::dvec3(frontPoint.x, 0, frontPoint.y) - a) > 0.0;
    const glm::dvec3 ll = faces ? a : b, lr = faces ? b : a;
    return {name, ll, lr, ll + glm::dvec3(0, kHeight, 0), {front, back}, WallKind::Virtual};
}

SceneDescription plantDescription() {
    SceneDescription d;
    d.name = "plant";
    d.models.push_back(ModelFile{"plant.glb", glm::dmat4(1.0), 1.0, UpAxis::Y, false, {"structure/*"}});
    d.cells = {{"A", rect(-40, -12, -20, 20), 0.0}, {"B", rect(-12, 12, -20, 0), 0.0}, {"C", rect(-12, 12, 0, 20), 0.0},
               {"D", rect(12, 40, -20, 0), 0.0},    {"E", rect(12, 40, 0, 20), 0.0}};
    d.walls = {wall("A|B", {-12, -20}, {-12, 0}, 0, 1, {-26, -10}), wall("A|C", {-12, 0}, {-12, 20}, 0, 2, {-26, 10}),
               wall("B|C", {-12, 0}, {12, 0}, 1, 2, {0, -10}),       wall("B|D", {12, -20}, {12, 0}, 1, 3, {0, -10}),
               wall("C|E", {12, 0}, {12, 20}, 2, 4, {0, 10}),        wall("D|E", {12, 0}, {40, 0}, 3, 4, {26, -10})};
    d.eyeHeight = kEye;
    d.headHeightRange = {1.2, 2.0};
    // Along the aisles: A -> B -> D -> E -> C -> A, crossing z = 0 only in the cross aisles.
    d.walkPath = {{-26, kEye, -10}, {0, kEye, -10}, {26, kEye, -10}, {26, kEye, 10},
                  {0, kEye, 10},    {-26, kEye, 10}, {-26, kEye, -10}};
    return d;
}

}  // namespace

GeneratedScene generatePlant(const GenerateOptions& options) {
    Rng rng(options.seed);
    GeneratedScene g;
    g.scene.name = "plant";
    plantStructure(g.scene);
    const std::vector<Placement> content = plantContent(rng);
    const std::size_t target = options.triangles ? options.triangles : 2'000'000;
    std::vector<Mesh> kinds = meshesForTarget(content, g.scene.triangleCount(), target, plantKinds);
    const int base = static_cast<int>(g.scene.meshes.size());
    for (Mesh& m : kinds) g.scene.meshes.push_back(std::move(m));
    for (const Placement& p : content) addObject(g.scene, base + p.kind, p.worldFromModel, p.name);
    g.description = plantDescription();
    return g;
}

}  // namespace cavewall::scenes
