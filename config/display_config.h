#pragma once
// Display configuration: the screens of a CAVE (or a power wall, or a desktop monitor), where
// their pixels go, the viewer's defaults, stereo, and tracker calibration.
//
// Plain data first (these structs), then parseDisplayConfig() (JSON -> structs, with type and
// range checks), then validateDisplayConfig() (geometric and cross-field rules). Runtime objects
// are built from a validated config by the display library. All positions are in the cave frame
// (config/conventions.h), in metres.
//
// File format (all keys except "screens" optional):
// {
//   "name": "cave4",
//   "screens": [{ "name": "front",
//                 "lowerLeft": [-1.5, 0, -1.5], "lowerRight": [1.5, 0, -1.5],
//                 "upperLeft": [-1.5, 3, -1.5], "resolution": [1024, 1024],
//                 "output": {"headless": {"file": "front"}}       // or:
//                 "output": {"window": {"monitor": 0, "position": [0, 0],
//                                       "size": [1024, 1024], "fullscreen": false,
//                                       "borderless": false,
//                                       "resize": "letterbox"}},  // or "reframe"
//                 "rank": 0,                                     // cluster mode only; optional
//                 "warp": "front.pfm", "blend": "front-blend.png",   // optional; relative to this file
//                 "blackLevel": 0.02 }],                         // or [r, g, b]; see docs/display.md
//   "viewer": { "headPosition": [0, 1.7, 0], "headOrientation": {"yawDeg": 0},
//               "eyeSeparation": 0.064, "near": 0.05, "far": 1000 },   // far: number or "infinite"
//   "stereo": "mono",        // mono | separate | side-by-side | top-bottom | anaglyph | quad-buffer
//   "minEyeDistance": 0.001, // see display/off_axis.h
//   "tracking": { "caveFromTracker": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],
//                 "latencyMs": 0,
//                 "volume": [[-3.5, -2, -3.5], [3.5, 5, 3.5]] }  // optional; see display_limits.h
// }

#include "config/error.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>

#include <array>
#include <filesystem>
#include <limits>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::config {

struct WindowOutput {
    int monitor = 0;  // monitor index (GLFW's order), for windowed and fullscreen windows
    // Top-left corner of the window's content, pixels from the monitor's top-left corner; none:
    // tiled with the other unplaced windows of its monitor (display/window_layout.h).
    std::optional<glm::ivec2> position;
    glm::ivec2 size{0, 0};  // window size in pixels; {0, 0} = the screen's resolution
    bool fullscreen = false;
    bool borderless = false;  // no title bar or frame (a projector's window)
    // A window resized to another shape: false ("letterbox") shows the image whole between
    // black bars, as a projector's fixed screen needs; true ("reframe") widens or narrows the
    // screen about its centre, keeping its height, to the window's shape (a desktop monitor).
    bool reframe = false;
    bool operator==(const WindowOutput&) const = default;
};

struct HeadlessOutput {
    std::string file;  // image file stem; empty = the screen's name
    bool operator==(const HeadlessOutput&) const = default;
};

struct Screen {
    std::string name;           // unique within the configuration
    glm::dvec3 lowerLeft{0.0};  // corners in the cave frame, metres
    glm::dvec3 lowerRight{0.0};
    glm::dvec3 upperLeft{0.0};
    glm::ivec2 resolution{0, 0};         // pixels, width x height
    std::optional<WindowOutput> window;  // unset = headless
    HeadlessOutput headless;
    int rank = -1;  // cluster mode: MPI rank that renders it; -1 = round-robin
    // Projector correction (display/warp_mesh.h, display/blend_mask.h), paths relative to the
    // configuration file's folder; empty = none.
    std::string warp;            // warp mesh: text (.warp) or MPCDI PFM file; empty = no warp
    std::string blend;           // blend mask: 8- or 16-bit grey PNG; empty = no blend
    glm::dvec3 blackLevel{0.0};  // linear-light RGB in [0, 1] added where this projector is alone
    bool corrected() const { return !warp.empty() || !blend.empty() || blackLevel != glm::dvec3(0.0); }
    bool operator==(const Screen&) const = default;
};

enum class StereoMode { Mono, Separate, SideBySide, TopBottom, Anaglyph, QuadBuffer };

struct Viewer {
    glm::dvec3 headPosition{0.0, 1.7, 0.0};          // default head position, cave frame
    glm::dquat headOrientation{1.0, 0.0, 0.0, 0.0};  // default head orientation (identity: looking down -Z)
    double eyeSeparation = 0.064;                    // metres, in [0, 0.2]
    double near = 0.05;                              // metres, in [1e-6, 1e6]
    double far = 1000.0;                             // metres, > near; +infinity = infinite far plane
    bool operator==(const Viewer&) const = default;
};

struct Tracking {
    glm::dmat4 caveFromTracker{1.0};  // calibration (metres): rotation (x uniform scale) + translation
    double latencyMs = 0.0;           // motion-to-photon latency to predict over, [0, 500]
    // Where tracked poses are plausible, [min corner, max corner] in the cave frame (metres);
    // unset: the default of config::trackingVolumeOf (display_limits.h).
    std::optional<std::array<glm::dvec3, 2>> volume;
    bool operator==(const Tracking&) const = default;
};

struct DisplayConfig {
    std::string name;             // defaults to the file stem
    std::vector<Screen> screens;  // at least one
    Viewer viewer;
    StereoMode stereo = StereoMode::Mono;
    double minEyeDistance = 1e-3;  // metres, in [1e-9, 1]; see display/off_axis.h
    Tracking tracking;
    // The folder the configuration was read from (loadDisplayConfig); screens' warp and blend
    // paths are relative to it. Not written back; empty for parsed text (the working folder).
    std::filesystem::path directory;
    bool operator==(const DisplayConfig&) const = default;
};

// Tolerances of the geometric validation rules, stated once.
inline constexpr double kMinScreenEdge = 1e-4;         // metres: shortest screen edge (0.1 mm)
inline constexpr double kMaxRightAngleErrorDeg = 0.1;  // corners must meet at 90° ± this
inline constexpr int kMaxResolution = 16384;           // pixels per side
inline constexpr double kMaxPixelAspectError = 0.02;   // warn when pixels are not square by more
inline constexpr double kMaxTiltDeg = 1.0;             // warn when a screen is this far from upright
                                                       // (or flat, for floors and ceilings)
inline constexpr double kMinCalibrationScale = 0.5;    // the uniform scale tracking.caveFromTracker
inline constexpr double kMaxCalibrationScale = 2.0;    // may carry, in [min, max]

// Parses JSON text into a DisplayConfig (types, ranges, unknown keys). `source` names the file
// in messages. Throws Error. Does not run the geometric rules: call validateDisplayConfig().
DisplayConfig parseDisplayConfig(std::string_view jsonText, const std::string& source);

// Checks the rules that span fields: rectangular, non-degenerate screens; unique names; each
// screen's front (the side lowerLeft->lowerRight x lowerLeft->upperLeft points to) facing the
// default head; near < far. Throws Error naming the source and the screen, with the fix.
void validateDisplayConfig(const DisplayConfig& config, const std::string& source);

// What is allowed but probably a mistake, one line per finding naming the source, the screen and
// the figure: pixels that are not square (the corners' aspect against the resolution's, more
// than kMaxPixelAspectError apart), screens tilted by more than kMaxTiltDeg from upright or
// flat, or rolled (a bottom edge that is not level). loadDisplayConfig prints them on stderr.
std::vector<std::string> displayWarnings(const DisplayConfig& config, const std::string& source);

// Reads, parses and validates a file. `nameOrPath` may also be a preset name ("cave4",
// "cave6", "powerwall", "desktop"), looked up in presetDirectory().
DisplayConfig loadDisplayConfig(const std::string& nameOrPath);

// The file loadDisplayConfig reads for `nameOrPath`: the path itself, or the preset's file.
// Throws Error for a bare name that is no preset.
std::filesystem::path displayConfigPath(const std::string& nameOrPath);

// The folder holding the preset configurations (config/ of the source tree, or
// $CAVEWALL_CONFIG_DIR when set).
std::filesystem::path presetDirectory();

std::string_view toString(StereoMode mode);

// A screen's warp or blend file (`relative` as written in the configuration) resolved against
// config.directory.
std::filesystem::path screenFilePath(const DisplayConfig& config, const std::string& relative);

// Cluster mode: the screens rank `rank` of `rankCount` renders, in configuration order. A screen
// with an explicit rank goes to that rank; the others are dealt round-robin by their index.
// Throws Error when a screen names a rank >= rankCount.
std::vector<int> screensOfRank(const DisplayConfig& config, int rank, int rankCount);

}  // namespace cavewall::config
