#pragma once
// A scene description (scenes/<name>/scene.json) as plain data: which glTF files make the
// scene, where they go, which objects are structure, and how the model is cut into cells by
// virtual walls (Ebbesmeyer's (1997) textured virtual walls) and portals (Aliaga & Lastra's
// (1997) portal textures). Parsing and validation live in scene_description_io.h.
//
// Frames: world (config/conventions.h): metres, +Y up. Floor regions are polygons in the
// (x, z) plane seen from above, counter-clockwise when viewed from +Y (i.e. going from +x
// towards -z). Wall quads use the lowerLeft/lowerRight/upperLeft convention; a wall's front
// side (its normal) faces cells[0], its back faces cells[1].

#include <glm/glm.hpp>

#include <array>
#include <filesystem>
#include <string>
#include <vector>

namespace cavewall::scenes {

enum class UpAxis { Y, Z };

struct ModelFile {
    std::filesystem::path file;               // glTF/GLB, relative to the scene.json folder
    glm::dmat4 worldFromFile{1.0};            // placement (after units and up-axis conversion)
    double metresPerUnit = 1.0;               // units conversion of the file
    UpAxis up = UpAxis::Y;                    // Z-up files are rotated to Y-up
    bool structure = false;                   // every object of this file is structure
    std::vector<std::string> structureNodes;  // node-name patterns ('*' wildcard) that are structure
    double splitMetres = 0.0;                 // > 0: objects wider cut into chunks (scenes/mesh_split.h)

    bool operator==(const ModelFile&) const = default;
};

struct Cell {
    std::string name;
    std::vector<glm::dvec2> region;  // convex floor polygon (x, z), CCW from above
    double floorY = 0.0;             // floor height

    bool operator==(const Cell&) const = default;
};

enum class WallKind {
    Virtual,  // a cut through open space: the cell behind shows as a texture
    Portal,   // a doorway in a real wall: the cell behind shows through it as a texture
};

struct VirtualWall {
    std::string name;
    glm::dvec3 lowerLeft{0.0}, lowerRight{0.0}, upperLeft{0.0};
    std::array<int, 2> cells{-1, -1};  // [front, back]: indices into SceneDescription::cells
    WallKind kind = WallKind::Virtual;

    bool operator==(const VirtualWall&) const = default;
};

// A real occluding wall (solid, drawn as geometry); visibility passes it only through portals.
struct RealWall {
    std::string name;
    glm::dvec3 lowerLeft{0.0}, lowerRight{0.0}, upperLeft{0.0};

    bool operator==(const RealWall&) const = default;
};

struct SceneDescription {
    std::string name;
    std::filesystem::path folder;  // where scene.json lives; files are relative to it
    std::vector<ModelFile> models;
    std::vector<Cell> cells;
    std::vector<VirtualWall> walls;
    std::vector<RealWall> realWalls;
    double eyeHeight = 1.7;                // metres above the floor for a walking viewer
    glm::dvec2 headHeightRange{1.2, 2.0};  // absolute head heights (y) the walls must serve
    std::vector<glm::dvec3> walkPath;      // default walk path (eye positions, world frame)
    // Indices into walkPath where a new piece of the walk starts: nothing is walked from the
    // point before to this one (storeys joined by no stair the geometry shows). Increasing, in
    // (0, walkPath.size()). Optional.
    std::vector<int> walkBreaks;
    // A second path (same frame) that hugs the virtual walls, within about 0.3 m of them and
    // across their blend strips: where the walls' bound is hardest to keep. Optional.
    std::vector<glm::dvec3> wallPath;
    // What the walls of this scene are planned and baked with when a command is not given its
    // own flag ("planning" in scene.json, as `cavewall walls` writes it for its proposal).
    // Optional: 0 is "not given", the commands' own defaults.
    struct Planning {
        double minZone = 0.0;  // smallest zone size, metres (--min-zone)
        int maxRes = 0;        // largest baked texture side, texels (--max-res, bench --bake-resolution)
        bool operator==(const Planning&) const = default;
    } planning;

    bool operator==(const SceneDescription&) const = default;
};

}  // namespace cavewall::scenes
