// The generated house: 18 m x 12 m, six 6 m x 6 m rooms (two rows of three), walls 2.8 m high
// and 0.15 m thick on the room boundaries, doorways 0.9 m x 2.1 m in the middle of the walls
// that connect R00-R01-R02-R12-R11-R10 (and R01-R11). Room Rrc is row r (z < 0 for r = 0),
// column c (x from -9). Furniture stands in the rooms' corners so the walk path (room centre
// -> doorway -> next room centre) stays clear.
#include "scenes/generate.h"
#include "scenes/generate_parts.h"
#include "scenes/primitives.h"

#include <glm/gtc/matrix_transform.hpp>

namespace cavewall::scenes {
namespace {

constexpr double kStoreyHeight = 2.8, kDoorWidth = 0.9, kDoorHeight = 2.1, kThickness = 0.15, kHouseEye = 1.6;

enum HouseKind { TableKind, ChairKind, SofaKind, BedKind, ShelfKind, LampKind };

std::vector<Mesh> houseKinds(int detail) {
    return {makeTable(detail), makeChair(detail), makeSofa(detail),
            makeBed(detail),   makeShelf(detail), makeLamp(detail)};
}

struct WallLine {
    glm::dvec2 a, b;            // floor points (x, z), axis-aligned
    int front = -1, back = -1;  // cells on either side when it has a door
    bool door = false;
};

std::string roomName(int row, int col) { return "R" + std::to_string(row) + std::to_string(col); }
int roomIndex(int row, int col) { return 3 * row + col; }
glm::dvec2 roomCentre(int row, int col) { return {-6.0 + 6.0 * col, -3.0 + 6.0 * row}; }

std::vector<WallLine> wallLines() {
    std::vector<WallLine> w = {{{-9, -6}, {9, -6}}, {{-9, 6}, {9, 6}}, {{-9, -6}, {-9, 6}}, {{9, -6}, {9, 6}}};
    for (int row = 0; row < 2; ++row)  // walls between columns, doors in both rows
        for (int col = 0; col < 2; ++col) {
            const double x = -3.0 + 6.0 * col, z0 = row == 0 ? -6.0 : 0.0;
            w.push_back({{x, z0}, {x, z0 + 6.0}, roomIndex(row, col), roomIndex(row, col + 1), true});
        }
    for (int col = 0; col < 3; ++col)  // walls between the rows; R00-R10 stays closed
        w.push_back({{-9.0 + 6.0 * col, 0}, {-3.0 + 6.0 * col, 0}, roomIndex(0, col), roomIndex(1, col), col > 0});
    return w;
}

// One solid rectangle of wall between floor points p and q, heights y0..y1: geometry (a box)
// and the matching zero-thickness RealWall on the centre line.
// Outer walls are lengthened by the thickness so the corners close; pieces next to doorways are not.
void addWallPiece(GeneratedScene& g, int boxMesh, glm::dvec2 p, glm::dvec2 q, double y0, double y1,
                  bool extend = false) {
    const glm::dvec2 d = q - p;
    const double len = glm::length(d);
    if (len < 1e-9) return;
    const glm::dvec2 c = 0.5 * (p + q);
    const bool alongX = std::abs(d.x) > std::abs(d.y);
    glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(c.x, 0.5 * (y0 + y1), c.y));
    const double l = extend ? len + kThickness : len;
    m = glm::scale(m, alongX ? glm::dvec3(l, y1 - y0, kThickness) : glm::dvec3(kThickness, y1 - y0, l));
    const std::string name = "structure/wall-" + std::to_string(g.description.realWalls.size());
    addObject(g.scene, boxMesh, m, name, Role::Structure);
    g.description.realWalls.push_back(
        {name.substr(10), glm::dvec3(p.x, y0, p.y), glm::dvec3(q.x, y0, q.y), glm::dvec3(p.x, y1, p.y)});
}

void addWalls(GeneratedScene& g) {
    g.scene.meshes.push_back(makeBox({1, 1, 1}, {0.86f, 0.84f, 0.8f, 1}));  // unit box, scaled per piece
    const int box = static_cast<int>(g.scene.meshes.size()) - 1;
    for (const WallLine& w : wallLines()) {
        if (!w.door) {
            addWallPiece(g, box, w.a, w.b, 0.0, kStoreyHeight, w.front < 0);
            continue;
        }
        const glm::dvec2 dir = glm::normalize(w.b - w.a), mid = 0.5 * (w.a + w.b);
        const glm::dvec2 d0 = mid - 0.5 * kDoorWidth * dir, d1 = mid + 0.5 * kDoorWidth * dir;
        addWallPiece(g, box, w.a, d0, 0.0, kStoreyHeight);
        addWallPiece(g, box, d1, w.b, 0.0, kStoreyHeight);
        addWallPiece(g, box, d0, d1, kDoorHeight, kStoreyHeight);  // lintel
        // The portal fills the doorway; its front faces cells[0] (w.front).
        const glm::dvec2 fc = roomCentre(w.front / 3, w.front % 3);
        const glm::dvec3 a(d0.x, 0, d0.y), b(d1.x, 0, d1.y);
        const bool faces = glm::dot(glm::cross(b - a, glm::dvec3(0, 1, 0)), glm::dvec3(fc.x, 0, fc.y) - a) > 0.0;
        const glm::dvec3 ll = faces ? a : b, lr = faces ? b : a;
        g.description.walls.push_back(
            {"door " + g.description.cells[w.front].name + "|" + g.description.cells[w.back].name,
             ll,
             lr,
             ll + glm::dvec3(0, kDoorHeight, 0),
             {w.front, w.back},
             WallKind::Portal});
    }
}

void addRoomsStructure(GeneratedScene& g) {
    const glm::vec4 floorA(0.62f, 0.5f, 0.38f, 1), floorB(0.56f, 0.45f, 0.34f, 1), ceiling(0.93f, 0.93f, 0.9f, 1);
    g.scene.meshes.push_back(makeTiledQuad({-3, 0, 3}, {6, 0, 0}, {0, 0, -6}, 12, 12, floorA, floorB));
    const int floorMesh = static_cast<int>(g.scene.meshes.size()) - 1;
    g.scene.meshes.push_back(
        makeTiledQuad({-3, static_cast<float>(kStoreyHeight), -3}, {6, 0, 0}, {0, 0, 6}, 2, 2, ceiling, ceiling));
    const int ceilingMesh = floorMesh + 1;
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col) {
            const glm::dvec2 c = roomCentre(row, col);
            const glm::dmat4 m = glm::translate(glm::dmat4(1.0), glm::dvec3(c.x, 0, c.y));
            addObject(g.scene, floorMesh, m, "structure/floor-" + roomName(row, col), Role::Structure);
            addObject(g.scene, ceilingMesh, m, "structure/ceiling-" + roomName(row, col), Role::Structure);
            g.description.cells.push_back(
                {roomName(row, col),
                 {{c.x - 3, c.y + 3}, {c.x + 3, c.y + 3}, {c.x + 3, c.y - 3}, {c.x - 3, c.y - 3}},
                 0.0});
        }
}

// Furniture in the four corners of every room; a corner holds one group chosen by the seed.
std::vector<Placement> furniture(Rng& rng) {
    std::vector<Placement> out;
    int n = 0;
    auto put = [&](int kind, glm::dvec2 p, double yawDeg) {
        const glm::dmat4 m = glm::rotate(glm::translate(glm::dmat4(1.0), glm::dvec3(p.x, 0, p.y)), glm::radians(yawDeg),
                                         glm::dvec3(0, 1, 0));
        static const char* names[] = {"table", "chair", "sofa", "bed", "shelf", "lamp"};
        out.push_back({kind, m, std::string(names[kind]) + "-" + std::to_string(n++)});
    };
    for (int row = 0; row < 2; ++row)
        for (int col = 0; col < 3; ++col)
            for (int corner = 0; corner < 4; ++corner) {
                const glm::dvec2 s((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0);
                const glm::dvec2 p = roomCentre(row, col) + 1.7 * s;
                const double facing = s.y > 0 ? 180.0 : 0.0;  // backs against the wall at z = centre + 3 s.y
                switch (rng.below(4)) {
                    case 0:
                        put(TableKind, p, 0.0);
                        for (int k = 0; k < 4; ++k)
                            put(ChairKind,
                                p + 0.75 * glm::dvec2(k == 0   ? 1
                                                      : k == 1 ? -1
                                                               : 0,
                                                      k == 2   ? 1
                                                      : k == 3 ? -1
                                                               : 0),
                                90.0 * k + 90.0);
                        break;
                    case 1:
                        put(SofaKind, p + glm::dvec2(0, 0.5 * s.y), facing);
                        put(LampKind, p - glm::dvec2(0.9 * s.x, -0.9 * s.y), 0.0);
                        break;
                    case 2: put(BedKind, p, facing); break;
                    default:
                        put(ShelfKind, p + glm::dvec2(0, 0.9 * s.y), facing);
                        put(ChairKind, p, facing + 180.0);
                        break;
                }
            }
    return out;
}

}  // namespace

GeneratedScene generateHouse(const GenerateOptions& options) {
    Rng rng(options.seed ^ 0x486F757365ull);  // "House": the plant and the house differ for one seed
    GeneratedScene g;
    g.scene.name = "house";
    g.description.name = "house";
    g.description.models.push_back(ModelFile{"house.glb", glm::dmat4(1.0), 1.0, UpAxis::Y, false, {"structure/*"}});
    addRoomsStructure(g);
    addWalls(g);
    const std::vector<Placement> content = furniture(rng);
    const std::size_t target = options.triangles ? options.triangles : 200'000;
    std::vector<Mesh> kinds = meshesForTarget(content, g.scene.triangleCount(), target, houseKinds);
    const int base = static_cast<int>(g.scene.meshes.size());
    for (Mesh& m : kinds) g.scene.meshes.push_back(std::move(m));
    for (const Placement& p : content) addObject(g.scene, base + p.kind, p.worldFromModel, p.name);
    g.description.eyeHeight = kHouseEye;
    g.description.headHeightRange = {1.2, 2.0};
    const int order[][2] = {{0, 0}, {0, 1}, {0, 2}, {1, 2}, {1, 1}, {1, 0}};
    for (int i = 0; i < 6; ++i) {
        const glm::dvec2 c = roomCentre(order[i][0], order[i][1]);
        if (i > 0) {  // through the doorway in the middle of the shared wall
            const glm::dvec2 prev = roomCentre(order[i - 1][0], order[i - 1][1]), door = 0.5 * (prev + c);
            g.description.walkPath.push_back({door.x, kHouseEye, door.y});
        }
        g.description.walkPath.push_back({c.x, kHouseEye, c.y});
    }
    return g;
}

}  // namespace cavewall::scenes
