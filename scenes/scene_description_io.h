#pragma once
// Reading and checking scene.json files (format documented in scene_description_io.cpp's
// header comment and in docs/scenes.md).

#include "scenes/scene_description.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace cavewall::scenes {

// Parses scene.json text; `source` names the file in messages, `folder` is where relative
// model paths are resolved. Throws cavewall::Error with the JSON path on bad types or keys.
SceneDescription parseSceneDescription(std::string_view jsonText, const std::string& source,
                                       const std::filesystem::path& folder);

// Every point of a scene description (model placements, cell regions, walls) lies within this
// distance of the origin on each axis, metres: 100 km is far beyond any building or plant.
inline constexpr double kMaxSceneCoordinate = 1e5;
// A wall's footprint must come within this distance (metres) of each cell it joins.
inline constexpr double kMaxWallCellGap = 0.5;

// Checks the rules that span fields (walls are rectangles, walls name existing cells, cells
// have convex non-degenerate regions, coordinates are within kMaxSceneCoordinate, walls touch
// the cells they join, the walk path stays inside the cells, ...). Throws Error.
void validateSceneDescription(const SceneDescription& description, const std::string& source);

// Reads, parses and validates a scene.json (or the scene.json inside a folder).
SceneDescription loadSceneDescription(const std::filesystem::path& path);

// Writes a description as scene.json text (used by the generators); parse(write(d)) == d.
std::string writeSceneDescription(const SceneDescription& description);

}  // namespace cavewall::scenes
