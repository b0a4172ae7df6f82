#include "config/display_config.h"

#include "config/display_limits.h"
#include "config/json_reader.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <set>
#include <utility>

namespace cavewall::config {

namespace {

std::string vecString(glm::dvec3 v) {
    return "[" + formatNumber(v.x) + ", " + formatNumber(v.y) + ", " + formatNumber(v.z) + "]";
}

StereoMode parseStereo(const JsonNode& node) {
    const std::string s = node.oneOf({"mono", "separate", "side-by-side", "top-bottom", "anaglyph", "quad-buffer"});
    if (s == "separate") return StereoMode::Separate;
    if (s == "side-by-side") return StereoMode::SideBySide;
    if (s == "top-bottom") return StereoMode::TopBottom;
    if (s == "anaglyph") return StereoMode::Anaglyph;
    if (s == "quad-buffer") return StereoMode::QuadBuffer;
    return StereoMode::Mono;
}

void checkFileName(const JsonNode& node, const std::string& name) {
    const std::string problem = fileNameProblem(name);
    if (!problem.empty()) node.fail(problem);
}

glm::dvec3 position(const JsonNode& node) {
    const glm::dvec3 v = node.vec3();
    for (int i = 0; i < 3; ++i)
        if (std::abs(v[i]) > kMaxCoordinate)
            node.fail("expected coordinates in [-" + formatNumber(kMaxCoordinate) + ", " +
                      formatNumber(kMaxCoordinate) + "] m, got " + vecString(v));
    return v;
}

void parseOutput(const JsonNode& node, Screen& screen) {
    node.expectKeys({"window", "headless"});
    if (node.has("window") == node.has("headless")) node.fail("expected exactly one of 'window' or 'headless'");
    if (auto h = node.find("headless")) {
        h->expectKeys({"file"});
        if (auto f = h->find("file")) {
            screen.headless.file = f->string();
            checkFileName(*f, screen.headless.file);
        }
        return;
    }
    const JsonNode w = node.at("window");
    w.expectKeys({"monitor", "position", "size", "fullscreen", "borderless", "resize"});
    WindowOutput out;
    if (auto n = w.find("monitor")) out.monitor = n->integer(0, 64);
    if (auto n = w.find("position")) out.position = n->ivec2(-kMaxResolution * 4, kMaxResolution * 4);
    if (auto n = w.find("size")) out.size = n->ivec2(1, kMaxResolution);
    if (auto n = w.find("fullscreen")) out.fullscreen = n->boolean();
    if (auto n = w.find("borderless")) out.borderless = n->boolean();
    if (auto n = w.find("resize")) out.reframe = n->oneOf({"letterbox", "reframe"}) == "reframe";
    screen.window = out;
}

std::string correctionFile(const JsonNode& node) {
    const std::string file = node.string();
    if (file.empty()) node.fail("expected a file path relative to the configuration, got an empty string");
    return file;
}

// A number (grey) or [r, g, b], each in [0, 1].
glm::dvec3 blackLevel(const JsonNode& node) {
    if (node.raw().is_number()) return glm::dvec3(node.number(0.0, 1.0));
    const std::vector<JsonNode> rgb = node.items(3, 3);
    return {rgb[0].number(0.0, 1.0), rgb[1].number(0.0, 1.0), rgb[2].number(0.0, 1.0)};
}

Screen parseScreen(const JsonNode& node) {
    node.expectKeys({"name", "lowerLeft", "lowerRight", "upperLeft", "resolution", "output", "rank", "warp", "blend",
                     "blackLevel"});
    Screen s;
    s.name = node.at("name").string();
    checkFileName(node.at("name"), s.name);
    s.lowerLeft = position(node.at("lowerLeft"));
    s.lowerRight = position(node.at("lowerRight"));
    s.upperLeft = position(node.at("upperLeft"));
    s.resolution = node.at("resolution").ivec2(1, kMaxResolution);
    if (auto out = node.find("output")) parseOutput(*out, s);
    if (auto r = node.find("rank")) s.rank = r->integer(0, 4095);
    if (auto n = node.find("warp")) s.warp = correctionFile(*n);
    if (auto n = node.find("blend")) s.blend = correctionFile(*n);
    if (auto n = node.find("blackLevel")) s.blackLevel = blackLevel(*n);
    return s;
}

Viewer parseViewer(const JsonNode& node) {
    node.expectKeys({"headPosition", "headOrientation", "eyeSeparation", "near", "far"});
    Viewer v;
    if (auto n = node.find("headPosition")) v.headPosition = position(*n);
    if (auto n = node.find("headOrientation")) v.headOrientation = n->rotation();
    if (auto n = node.find("eyeSeparation")) v.eyeSeparation = n->number(0.0, 0.2);
    if (auto n = node.find("near")) v.near = n->number(1e-6, 1e6);
    if (auto n = node.find("far")) {
        if (n->raw().is_string()) {
            n->oneOf({"infinite"});
            v.far = std::numeric_limits<double>::infinity();
        } else {
            v.far = n->number(1e-6, 1e12);
        }
    }
    return v;
}

// [[x0, y0, z0], [x1, y1, z1]]: the first corner below the second on every axis, both within
// kMaxCoordinate.
std::array<glm::dvec3, 2> parseVolume(const JsonNode& node) {
    const std::vector<JsonNode> corners = node.items(2, 2);
    const std::array<glm::dvec3, 2> v{corners[0].vec3(), corners[1].vec3()};
    for (int c = 0; c < 2; ++c)
        for (int a = 0; a < 3; ++a)
            if (std::abs(v[c][a]) > kMaxCoordinate)
                corners[c].fail("expected coordinates within " + formatNumber(kMaxCoordinate) + " m, got " +
                                formatNumber(v[c][a]) + " m");
    for (int a = 0; a < 3; ++a)
        if (!(v[0][a] < v[1][a]))
            node.fail(std::string("expected the first corner below the second on every axis, got ") + "xyz"[a] + " " +
                      formatNumber(v[0][a]) + " >= " + formatNumber(v[1][a]));
    return v;
}

Tracking parseTracking(const JsonNode& node) {
    node.expectKeys({"caveFromTracker", "latencyMs", "volume"});
    Tracking t;
    if (auto n = node.find("caveFromTracker")) {
        t.caveFromTracker = n->mat4Rows();
        const glm::dvec4 lastRow(t.caveFromTracker[0][3], t.caveFromTracker[1][3], t.caveFromTracker[2][3],
                                 t.caveFromTracker[3][3]);
        if (lastRow != glm::dvec4(0, 0, 0, 1)) n->fail("expected the last row to be [0, 0, 0, 1] (a rigid transform)");
        const glm::dmat3 m(t.caveFromTracker);
        const double scale = std::cbrt(glm::determinant(m));
        if (!(scale >= kMinCalibrationScale && scale <= kMaxCalibrationScale))
            n->fail("expected a rotation, or a rotation times a uniform scale in [" +
                    formatNumber(kMinCalibrationScale) + ", " + formatNumber(kMaxCalibrationScale) +
                    "], in the upper 3x3, got det " + formatNumber(glm::determinant(m)) +
                    (scale < 0 ? " (a reflection)" : ""));
        const glm::dmat3 r = m / scale;
        const glm::dmat3 rtr = glm::transpose(r) * r;
        double worst = 0.0;
        for (int i = 0; i < 3; ++i)
            for (int j = 0; j < 3; ++j) worst = std::max(worst, std::abs(rtr[i][j] - (i == j)));
        if (worst > 1e-4)
            n->fail(
                "expected a rotation, or a rotation times a uniform scale, in the upper 3x3 (orthonormal within "
                "1e-4 after dividing by the scale " +
                formatNumber(scale) + "), got an error of " + formatNumber(worst));
    }
    for (int r = 0; r < 3; ++r)
        if (std::abs(t.caveFromTracker[3][r]) > kMaxCoordinate)
            node.at("caveFromTracker")
                .fail("expected a translation within " + formatNumber(kMaxCoordinate) + " m, got " +
                      formatNumber(t.caveFromTracker[3][r]) + " m");
    if (auto n = node.find("latencyMs")) t.latencyMs = n->number(0.0, 500.0);
    if (auto n = node.find("volume")) t.volume = parseVolume(*n);
    return t;
}

}  // namespace

std::string_view toString(StereoMode mode) {
    switch (mode) {
        case StereoMode::Mono: return "mono";
        case StereoMode::Separate: return "separate";
        case StereoMode::SideBySide: return "side-by-side";
        case StereoMode::TopBottom: return "top-bottom";
        case StereoMode::Anaglyph: return "anaglyph";
        case StereoMode::QuadBuffer: return "quad-buffer";
    }
    return "?";
}

DisplayConfig parseDisplayConfig(std::string_view jsonText, const std::string& source) {
    const JsonDocument doc = JsonDocument::fromText(jsonText, source);
    const JsonNode root = doc.root();
    root.expectKeys({"name", "screens", "viewer", "stereo", "minEyeDistance", "tracking"});
    DisplayConfig c;
    c.name = root.has("name") ? root.at("name").string() : std::filesystem::path(source).stem().string();
    for (const JsonNode& s : root.at("screens").items(1, 256)) c.screens.push_back(parseScreen(s));
    if (auto n = root.find("viewer")) c.viewer = parseViewer(*n);
    if (auto n = root.find("stereo")) c.stereo = parseStereo(*n);
    if (auto n = root.find("minEyeDistance")) c.minEyeDistance = n->number(1e-9, 1.0);
    if (auto n = root.find("tracking")) c.tracking = parseTracking(*n);
    return c;
}

void validateDisplayConfig(const DisplayConfig& config, const std::string& source) {
    std::set<std::string> names, stems;
    for (std::size_t i = 0; i < config.screens.size(); ++i) {
        const Screen& s = config.screens[i];
        const std::string where = source + ": screens[" + std::to_string(i) + "] '" + s.name + "'";
        if (!names.insert(s.name).second) throw Error(where + ": duplicate screen name (expected unique names)");
        for (const std::string& n : {s.name, s.headless.file})
            if (!n.empty() && !fileNameProblem(n).empty()) throw Error(where + ": " + fileNameProblem(n));
        std::string stem = s.headless.file.empty() ? s.name : s.headless.file;
        for (char& c : stem) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
        if (!stems.insert(stem).second)
            throw Error(where + ": image file '" + stem +
                        "' is also another screen's (expected unique names and "
                        "headless files, compared ignoring case)");
        for (const glm::dvec3& corner : {s.lowerLeft, s.lowerRight, s.upperLeft})
            for (int a = 0; a < 3; ++a)
                if (!(std::abs(corner[a]) <= kMaxCoordinate))
                    throw Error(where + ": corner " + vecString(corner) +
                                " is out of range (expected coordinates in [-" + formatNumber(kMaxCoordinate) + ", " +
                                formatNumber(kMaxCoordinate) + "] m)");
        const glm::dvec3 right = s.lowerRight - s.lowerLeft;
        const glm::dvec3 up = s.upperLeft - s.lowerLeft;
        const double width = glm::length(right), height = glm::length(up);
        const double area = glm::length(glm::cross(right, up));
        if (area < kMinScreenEdge * kMinScreenEdge && width >= kMinScreenEdge && height >= kMinScreenEdge)
            throw Error(where + ": corners are collinear (expected a non-zero area, got " + formatNumber(area) +
                        " m²)");
        if (width < kMinScreenEdge || height < kMinScreenEdge)
            throw Error(where + ": screen is degenerate (expected width and height of at least " +
                        formatNumber(kMinScreenEdge) + " m, got " + formatNumber(width) + " m × " +
                        formatNumber(height) + " m; lowerLeft " + vecString(s.lowerLeft) + ", lowerRight " +
                        vecString(s.lowerRight) + ", upperLeft " + vecString(s.upperLeft) + ")");
        const double angleDeg = glm::degrees(std::acos(std::clamp(glm::dot(right, up) / (width * height), -1.0, 1.0)));
        if (std::abs(angleDeg - 90.0) > kMaxRightAngleErrorDeg)
            throw Error(where + ": corners are not a rectangle (expected the edges at lowerLeft to meet at 90° ± " +
                        formatNumber(kMaxRightAngleErrorDeg) + "°, got " + formatNumber(angleDeg) + "°)");
        // The head must see the screen's front, where off-axis projection puts the image.
        const glm::dvec3 front = glm::normalize(glm::cross(right, up));
        const double ahead = glm::dot(front, config.viewer.headPosition - s.lowerLeft);
        if (!(ahead > 0.0))
            throw Error(where + ": faces away from the default head " + vecString(config.viewer.headPosition) +
                        " (its front, lowerLeft->lowerRight x lowerLeft->upperLeft, points to " + vecString(front) +
                        "; the head is " + formatNumber(-ahead) +
                        " m behind it); expected the head in front: swap lowerLeft with lowerRight and make "
                        "upperLeft the corner above the new lowerLeft, as seen from inside the CAVE");
    }
    const Viewer& v = config.viewer;
    if (!(v.near < v.far))
        throw Error(source + ": viewer: near must be less than far (got near " + formatNumber(v.near) + " m, far " +
                    formatNumber(v.far) + " m)");
}

std::vector<std::string> displayWarnings(const DisplayConfig& config, const std::string& source) {
    std::vector<std::string> out;
    char text[320];
    for (std::size_t i = 0; i < config.screens.size(); ++i) {
        const Screen& s = config.screens[i];
        const std::string where = source + ": screens[" + std::to_string(i) + "] '" + s.name + "'";
        const glm::dvec3 right = s.lowerRight - s.lowerLeft, up = s.upperLeft - s.lowerLeft;
        const double width = glm::length(right), height = glm::length(up);
        const double pixelAspect = (width / s.resolution.x) / (height / s.resolution.y);
        if (std::abs(pixelAspect - 1.0) > kMaxPixelAspectError) {
            std::snprintf(text, sizeof text,
                          ": pixels are not square: %.3f x %.3f m at %d x %d pixels gives pixels %.3f times as wide "
                          "as high (expected 1 within %.2f; check the resolution against the corners)",
                          width, height, s.resolution.x, s.resolution.y, pixelAspect, kMaxPixelAspectError);
            out.push_back(where + text);
        }
        // Upright: the front horizontal; flat (floor, ceiling): the front along +-y.
        const glm::dvec3 front = glm::normalize(glm::cross(right, up));
        const double fromUpright = glm::degrees(std::asin(std::clamp(std::abs(front.y), 0.0, 1.0)));
        const double fromFlat = 90.0 - fromUpright;
        const double rolled = glm::degrees(std::asin(std::clamp(std::abs(right.y) / width, 0.0, 1.0)));
        if (std::min(fromUpright, fromFlat) > kMaxTiltDeg) {
            std::snprintf(text, sizeof text,
                          ": tilted %.1f deg from upright (%.1f deg from flat); expected within %.1f deg of either "
                          "unless the screen really is tilted",
                          fromUpright, fromFlat, kMaxTiltDeg);
            out.push_back(where + text);
        } else if (fromUpright <= kMaxTiltDeg && rolled > kMaxTiltDeg) {
            std::snprintf(text, sizeof text, ": the bottom edge rises %.1f deg (expected level within %.1f deg)",
                          rolled, kMaxTiltDeg);
            out.push_back(where + text);
        }
    }
    return out;
}

std::vector<int> screensOfRank(const DisplayConfig& config, int rank, int rankCount) {
    std::vector<int> out;
    for (int i = 0; i < static_cast<int>(config.screens.size()); ++i) {
        const int r = config.screens[i].rank;
        if (r >= rankCount)
            throw Error(config.name + ": screens[" + std::to_string(i) + "] '" + config.screens[i].name + "': rank " +
                        std::to_string(r) + " does not exist (expected a rank below " + std::to_string(rankCount) +
                        ", the number of processes)");
        if ((r >= 0 ? r : i % rankCount) == rank) out.push_back(i);
    }
    return out;
}

namespace {

// The warp and blend files must exist; their contents are read by the display library.
void checkCorrectionFiles(const DisplayConfig& config, const std::string& source) {
    for (std::size_t i = 0; i < config.screens.size(); ++i) {
        const Screen& s = config.screens[i];
        const std::string where = source + ": screens[" + std::to_string(i) + "] '" + s.name + "'";
        for (const auto& [key, file] : {std::pair{"warp", s.warp}, std::pair{"blend", s.blend}}) {
            if (file.empty()) continue;
            const std::filesystem::path p = screenFilePath(config, file);
            if (!std::filesystem::is_regular_file(p))
                throw Error(where + ": " + key + " file '" + file + "' not found (expected a file at " + p.string() +
                            ", relative to the configuration's folder)");
        }
    }
}

}  // namespace

std::filesystem::path presetDirectory() {
    if (const char* dir = std::getenv("CAVEWALL_CONFIG_DIR"); dir && *dir) return dir;
    return CAVEWALL_PRESET_DIR;
}

std::filesystem::path displayConfigPath(const std::string& nameOrPath) {
    std::filesystem::path path(nameOrPath);
    const bool bareName = !path.has_parent_path() && !path.has_extension();
    if (bareName) path = presetDirectory() / (nameOrPath + ".json");
    if (!bareName) return path;
    std::error_code error;
    if (!std::filesystem::exists(path, error))
        throw Error(nameOrPath + ": " +
                    (error ? "cannot read the preset " + path.string() + " (" + error.message() + ")"
                           : "no such display configuration") +
                    " (expected a file path or one of the presets cave4, cave6, powerwall, desktop in " +
                    presetDirectory().string() + ")");
    return path;
}

std::filesystem::path screenFilePath(const DisplayConfig& config, const std::string& relative) {
    return config.directory / relative;
}

DisplayConfig loadDisplayConfig(const std::string& nameOrPath) {
    const std::filesystem::path path = displayConfigPath(nameOrPath);
    DisplayConfig config = parseDisplayConfig(readTextFile(path), path.string());
    config.directory = path.parent_path();
    validateDisplayConfig(config, path.string());
    checkCorrectionFiles(config, path.string());
    for (const std::string& w : displayWarnings(config, path.string())) std::cerr << "warning: " << w << "\n";
    return config;
}

}  // namespace cavewall::config
