#pragma once
// Limits on what a display configuration may say beyond its types (hostile input).
//
// - Coordinates: every screen corner, the default head and the calibration's translation lie
//   within kMaxCoordinate metres of the cave origin on each axis (a 1 km display is already
//   absurd; beyond ~1e150 the frustum's products overflow to NaN).
// - Names that become file names (screen names and headless.file): 1 to 64 characters from
//   A-Z a-z 0-9 '_' '-' '.', not starting with '.' or '-' (no hidden files, no "..", nothing
//   read as a flag), and not a name the program writes itself ("foldout", "bench", in any
//   case). Outputs then stay inside the output folder whatever the configuration says.
// - The tracking volume: where a tracked head or hand may plausibly be. Poses outside it (a
//   corrupt or hostile packet) are dropped and counted like malformed packets.

#include "config/display_config.h"

#include <glm/glm.hpp>

#include <string>
#include <string_view>

namespace cavewall::config {

inline constexpr double kMaxCoordinate = 1000.0;  // metres, per axis
inline constexpr double kTrackingMargin = 2.0;    // metres the default volume extends past the screens

// Why `name` breaks the file-name rule above ("expected only letters, digits, ..., got '../x'"),
// or "" when it follows it.
std::string fileNameProblem(std::string_view name);

// An axis-aligned box in the cave frame, metres.
struct TrackingVolume {
    glm::dvec3 min{-kMaxCoordinate};
    glm::dvec3 max{kMaxCoordinate};
    bool contains(const glm::dvec3& p) const {
        return p.x >= min.x && p.y >= min.y && p.z >= min.z && p.x <= max.x && p.y <= max.y && p.z <= max.z;
    }
    bool operator==(const TrackingVolume&) const = default;
};

// The tracking volume of a display: tracking.volume when the configuration sets it, else the
// bounding box of its screens' corners and its default head, grown by kTrackingMargin on every
// side (cave4: x and z in [-3.5, 3.5], y in [-2, 5]). A tracker spec's `volume` parameter
// overrides both (input/tracker_source.h).
TrackingVolume trackingVolumeOf(const DisplayConfig& config);

}  // namespace cavewall::config
