// The generated production hall. Layout of the default (top view, x right, z down; metres):
//
//   z=-20  +----+----+----+----+----+----+----+----+
//          | N1 | N2 | N3 | N4 | N5 | N6 | N7 | N8 |   machine row z = -17, aisle z = -10
//   z=-7.2 +----+----+----+----+----+----+----+----+
//          | M1 | M2 | M3 | M4 | M5 | M6 | M7 | M8 |   machine rows z = -3 and 3, conveyors
//   z=7.2  +----+----+----+----+----+----+----+----+
//          | S1 | S2 | S3 | S4 | S5 | S6 | S7 | S8 |   aisle z = 10, machine row z = 17
//   z=+20  +----+----+----+----+----+----+----+----+
//         x=-40                                   x=40
//
// 24 cells of 10 m (x) split by virtual walls at x = -30, -20, ..., 30 and z = +-7.2 (37
// walls). Larger triangle targets make the hall longer, not the parts denser: 8 cell columns
// per 2 M triangles (plantColumns), so a cell holds about the same geometry at every size, as
// in a real plant that grows by bays. Parts of one kind and detail share one mesh (as a CAD
// export shares an assembly's parts); the structure is unique per hall. The walk path runs along both aisles, in the light aisle cells (one machine row,
// cabinets on the long wall, a pipe rack overhead), and crosses between them at x = +-37,
// where the end cells leave a cross aisle. The middle cells hold the two inner rows and the
// conveyors between them. Nothing crosses a virtual wall, so each object lies in one cell;
// columns on z = 0 and roof beams are structure.
#include "scenes/generate.h"
#include "scenes/generate_parts.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>

namespace cavewall::scenes {
namespace {

constexpr double kHalfZ = 20.0, kHeight = 8.0, kEye = 1.7;
constexpr double kOuterRow = 17.0, kInnerRow = 3.0, kConveyor = 1.0, kAisle = 10.0, kSplit = 7.2;
constexpr double kHug = 0.3;  // metres from the walls along the wall path

enum Kind { Machine0, Machine1, Machine2, RobotKind, ConveyorKind, CabinetKind, RackKind, KindCount };

std::vector<Mesh> plantKinds(int detail) {
    return {makeMachineTool(0, detail), makeMachineTool(1, detail), makeMachineTool(2, detail), makeRobot(detail),
            makeConveyor(detail),       makeCabinet(detail),        makePipeRack(detail)};
}

glm::dmat4 place(double x, double z, double yawDeg) {
    return glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(x, 0, z)), glm::radians(yawDeg), glm::dvec3(0, 1, 0));
}

constexpr int kColumnsPerStep = 8;  // cell columns (10 m wide) per kTrianglesPerStep
constexpr std::size_t kTrianglesPerStep = 2'000'000;
constexpr int kMaxColumns = 8 * 64;  // a 5.12 km hall

// Cell columns for a triangle target: 8 per 2 M triangles, the target rounded to the nearest
// 2 M (at least one step), so the default and every target below 3 M keep the 80 m hall.
int plantColumns(std::size_t target) {
    const std::size_t steps = std::max<std::size_t>(1, (target + kTrianglesPerStep / 2) / kTrianglesPerStep);
    return static_cast<int>(std::min<std::size_t>(kMaxColumns, kColumnsPerStep * steps));
}

double halfX(int columns) { return 5.0 * columns; }
double columnCentre(int columns, int j) { return -halfX(columns) + 5.0 + 10.0 * j; }

void addStation(std::vector<Placement>& out, Rng& rng, double x, double rowZ, int& n) {
    const std::string id = std::to_string(n++);
    const bool facingAisle = std::abs(rowZ) > 10.0 ? rowZ < 0 : rowZ > 0;  // outer rows face inwards
    const double towardsAisle = (std::abs(rowZ) > 10.0) == (rowZ < 0) ? 1.0 : -1.0;
    out.push_back({Machine0 + rng.below(3), place(x, rowZ, facingAisle ? 0.0 : 180.0), "machine-" + id});
    if (rng.chance(0.6))  // robots stand between the machine and the aisle
        out.push_back({RobotKind, place(x + rng.uniform(-0.5, 0.5), rowZ + 2.6 * towardsAisle, rng.uniform(0, 360)),
                       "robot-" + id});
    if (std::abs(rowZ) < 10.0 && rng.chance(0.5))  // conveyors between the inner rows and z = 0
        out.push_back({ConveyorKind, place(x, rowZ > 0 ? kConveyor : -kConveyor, 0.0), "conveyor-" + id});
}

std::vector<Placement> plantContent(Rng& rng, int columns) {
    std::vector<Placement> out;
    int n = 0;
    // Machines reach 1 m across their row, robots 2.6 m + 1.45 m towards the aisle: the inner
    // rows stay inside z = +-7.05, the outer rows outside +-12.95, clear of the walls at +-7.2.
    for (double z : {-kOuterRow, -kInnerRow, kInnerRow, kOuterRow}) {
        for (int j = 0; j < columns; ++j) {
            const double c = columnCentre(columns, j);
            const bool endColumn = j == 0 || j == columns - 1, inner = std::abs(z) < 10.0;
            // Stations at c +- 2.5 (machines reach 2.3 m, robots 2 m): clear of the walls at c +- 5.
            // The end cells' inner rows keep only the station away from the cross aisle.
            for (double dx : {-2.5, 2.5})
                if (!(endColumn && inner && (j == 0) == (dx < 0))) addStation(out, rng, c + dx, z, n);
        }
    }
    for (double side : {-1.0, 1.0}) {
        for (int j = 0; j < columns; ++j) {
            const double c = columnCentre(columns, j);
            // Cabinets against the long walls, backs to the wall; one 8 m pipe rack overhead.
            for (double dx : {-3.75, -1.25, 1.25, 3.75}) {
                if (!rng.chance(0.55)) continue;
                out.push_back({CabinetKind, place(c + dx, side * (kHalfZ - 0.35), side < 0 ? 0.0 : 180.0),
                               "cabinet-" + std::to_string(n++)});
            }
            out.push_back({RackKind, place(c, side * 18.5, 0.0), "pipe-rack-" + std::to_string(n++)});
        }
    }
    return out;
}

void addStructure(Scene& s, Mesh mesh, const std::vector<glm::dmat4>& where, const std::string& name) {
    s.meshes.push_back(std::move(mesh));
    for (std::size_t i = 0; i < where.size(); ++i)
        addObject(s, static_cast<int>(s.meshes.size()) - 1, where[i],
                  "structure/" + name + (where.size() > 1 ? "-" + std::to_string(i) : ""), Role::Structure);
}

void plantStructure(Scene& s, int columns) {
    const glm::vec4 floorA(0.55f, 0.56f, 0.55f, 1), floorB(0.48f, 0.49f, 0.5f, 1);
    const glm::vec4 wallA(0.78f, 0.76f, 0.7f, 1), wallB(0.72f, 0.7f, 0.64f, 1), roof(0.6f, 0.62f, 0.66f, 1);
    const float hx = static_cast<float>(halfX(columns)), hz = static_cast<float>(kHalfZ),
                h = static_cast<float>(kHeight);
    const glm::dmat4 id(1.0);
    // Tiles per 80 m of hall as in the default: floor 40, roof 10, long walls 20.
    const int floorTiles = 5 * columns, roofTiles = (10 * columns + 4) / 8, wallTiles = (20 * columns + 4) / 8;
    addStructure(s, makeTiledQuad({-hx, 0, hz}, {2 * hx, 0, 0}, {0, 0, -2 * hz}, floorTiles, 20, floorA, floorB), {id},
                 "floor");
    addStructure(s, makeTiledQuad({-hx, h, -hz}, {2 * hx, 0, 0}, {0, 0, 2 * hz}, roofTiles, 5, roof, roof), {id},
                 "roof");
    addStructure(s, makeTiledQuad({-hx, 0, -hz}, {2 * hx, 0, 0}, {0, h, 0}, wallTiles, 2, wallA, wallB), {id},
                 "wall-north");
    addStructure(s, makeTiledQuad({hx, 0, hz}, {-2 * hx, 0, 0}, {0, h, 0}, wallTiles, 2, wallA, wallB), {id},
                 "wall-south");
    addStructure(s, makeTiledQuad({-hx, 0, hz}, {0, 0, -2 * hz}, {0, h, 0}, 10, 2, wallA, wallB), {id}, "wall-west");
    addStructure(s, makeTiledQuad({hx, 0, -hz}, {0, 0, 2 * hz}, {0, h, 0}, 10, 2, wallA, wallB), {id}, "wall-east");
    std::vector<glm::dmat4> pillars, beams;
    for (int j = 1; j < columns; ++j)
        pillars.push_back(glm::translate(id, glm::dvec3(-hx + 10.0 * j, 0.5 * kHeight, 0)));
    addStructure(s, makeBox({0.5f, h, 0.5f}, {0.7f, 0.7f, 0.72f, 1}), pillars, "column");
    for (int k = 0; 4.0 + 8.0 * k < 2.0 * hx; ++k)
        beams.push_back(glm::translate(id, glm::dvec3(-hx + 4.0 + 8.0 * k, kHeight - 0.35, 0)));
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

SceneDescription plantDescription(int columns) {
    SceneDescription d;
    d.name = "plant";
    d.models.push_back(ModelFile{"plant.glb", glm::dmat4(1.0), 1.0, UpAxis::Y, false, {"structure/*"}});
    const double rowEdges[4] = {-kHalfZ, -kSplit, kSplit, kHalfZ};
    const double hx = halfX(columns);
    for (int r = 0; r < 3; ++r)
        for (int j = 0; j < columns; ++j) {
            const double x0 = -hx + 10.0 * j;
            d.cells.push_back({std::string(1, "NMS"[r]) + std::to_string(j + 1),
                               rect(x0, x0 + 10.0, rowEdges[r], rowEdges[r + 1]), 0.0});
        }
    auto cellName = [&](int i) { return d.cells[i].name; };
    for (int r = 0; r < 3; ++r)
        for (int j = 0; j + 1 < columns; ++j) {  // x walls between neighbours in a row
            const int a = r * columns + j, b = a + 1;
            const double x = -hx + 10.0 * (j + 1), z0 = rowEdges[r], z1 = rowEdges[r + 1];
            d.walls.push_back(
                wall(cellName(a) + "|" + cellName(b), {x, z0}, {x, z1}, a, b, {x - 5.0, 0.5 * (z0 + z1)}));
        }
    for (int r = 0; r < 2; ++r)
        for (int j = 0; j < columns; ++j) {  // z walls between the rows
            const int a = r * columns + j, b = a + columns;
            const double x0 = -hx + 10.0 * j, z = rowEdges[r + 1];
            d.walls.push_back(
                wall(cellName(a) + "|" + cellName(b), {x0, z}, {x0 + 10.0, z}, a, b, {x0 + 5.0, z - 1.0}));
        }
    d.eyeHeight = kEye;
    d.headHeightRange = {1.2, 2.0};
    // Along the north aisle through N1 ... N8, across through M8, back along the south aisle,
    // across through M1 (the end cells' cross aisles, 3 m from the end walls).
    const double end = hx - 3.0;
    d.walkPath = {
        {-end, kEye, -kAisle}, {end, kEye, -kAisle}, {end, kEye, kAisle}, {-end, kEye, kAisle}, {-end, kEye, -kAisle}};
    // kHug from the walls: along the N|M walls on both sides, along M1|M2, along the M|S walls
    // on both sides with a detour along S2|S3 on both sides; every crossing of a wall between
    // two cells of a row passes through both cells' geometry zones and blend strips.
    const double n = -kSplit - kHug, m0 = -kSplit + kHug, m1 = kSplit - kHug, s = kSplit + kHug;
    const double w1 = -hx + 10.0, w2 = -hx + 20.0, top = kHalfZ - 0.5;  // M1|M2, S2|S3
    d.wallPath = {{-end, kEye, n},       {end, kEye, n},         {end, kEye, m0},        {-end, kEye, m0},
                  {w1 - kHug, kEye, m0}, {w1 - kHug, kEye, m1},  {end, kEye, m1},        {end, kEye, s},
                  {w2 - kHug, kEye, s},  {w2 - kHug, kEye, top}, {w2 + kHug, kEye, top}, {w2 + kHug, kEye, s},
                  {-end, kEye, s}};
    return d;
}

}  // namespace

GeneratedScene generatePlant(const GenerateOptions& options) {
    Rng rng(options.seed);
    GeneratedScene g;
    g.scene.name = "plant";
    const std::size_t target = options.triangles ? options.triangles : 2'000'000;
    const int columns = plantColumns(target);
    plantStructure(g.scene, columns);
    const std::vector<Placement> content = plantContent(rng, columns);
    std::vector<Mesh> kinds = meshesForTarget(content, g.scene.triangleCount(), target, plantKinds);
    const int base = static_cast<int>(g.scene.meshes.size());
    for (Mesh& m : kinds) g.scene.meshes.push_back(std::move(m));
    for (const Placement& p : content) addObject(g.scene, base + p.kind, p.worldFromModel, p.name);
    g.description = plantDescription(columns);
    return g;
}

}  // namespace cavewall::scenes
