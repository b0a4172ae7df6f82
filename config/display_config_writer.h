#pragma once
// Writing a display configuration back to JSON, in the file format of config/display_config.h.
//
// The writer round-trips: parseDisplayConfig(displayConfigJson(c), source) == c for every
// config parseDisplayConfig returns (numbers are written in the shortest form that reads back
// to the same double; all but `directory`, which is where a file was read from; the head orientation as a unit quaternion [x, y, z, w]; caveFromTracker
// as four rows). Keys are written in the order of the format's description; optional keys at
// their default (rank -1, no window position, no volume, an empty headless file) are left out.

#include "config/display_config.h"

#include <string>

namespace cavewall::config {

// The configuration as JSON text, indented by two spaces, ending with a newline.
std::string displayConfigJson(const DisplayConfig& config);

}  // namespace cavewall::config
