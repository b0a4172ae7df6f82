#pragma once
// Reading and checking scene.json files (format documented in scene_description_io.cpp's
// header comment and in the README).

#include "scenes/scene_description.h"

#include <filesystem>
#include <string>
#include <string_view>

namespace cavewall::scenes {

// Parses scene.json text; `source` names the file in messages, `folder` is where relative
// model paths are resolved. Throws cavewall::Error with the JSON path on bad types or keys.
SceneDescription parseSceneDescription(std::string_view jsonText, const std::string& source,
                                       const std::filesystem::path& folder);

// Checks the rules that span fields (walls are rectangles, walls name existing cells, cells
// have convex non-degenerate regions, the walk path stays inside the cells, ...). Throws Error.
void validateSceneDescription(const SceneDescription& description, const std::string& source);

// Reads, parses and validates a scene.json (or the scene.json inside a folder).
SceneDescription loadSceneDescription(const std::filesystem::path& path);

// Writes a description as scene.json text (used by the generators); parse(write(d)) == d.
std::string writeSceneDescription(const SceneDescription& description);

}  // namespace cavewall::scenes
