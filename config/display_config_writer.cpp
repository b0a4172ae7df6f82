#include "config/display_config_writer.h"

#include <nlohmann/json.hpp>

#include <cmath>

namespace cavewall::config {

namespace {

using Json = nlohmann::ordered_json;

Json vec(const glm::dvec3& v) { return Json::array({v.x, v.y, v.z}); }
Json ivec(const glm::ivec2& v) { return Json::array({v.x, v.y}); }

Json screenJson(const Screen& s) {
    Json j;
    j["name"] = s.name;
    j["lowerLeft"] = vec(s.lowerLeft);
    j["lowerRight"] = vec(s.lowerRight);
    j["upperLeft"] = vec(s.upperLeft);
    j["resolution"] = ivec(s.resolution);
    if (s.window) {
        Json w;
        w["monitor"] = s.window->monitor;
        if (s.window->position) w["position"] = ivec(*s.window->position);
        if (s.window->size != glm::ivec2(0, 0)) w["size"] = ivec(s.window->size);
        w["fullscreen"] = s.window->fullscreen;
        w["borderless"] = s.window->borderless;
        if (s.window->reframe) w["resize"] = "reframe";
        j["output"] = {{"window", w}};
    } else if (!s.headless.file.empty()) {
        j["output"] = {{"headless", {{"file", s.headless.file}}}};
    }
    if (s.rank >= 0) j["rank"] = s.rank;
    if (!s.warp.empty()) j["warp"] = s.warp;
    if (!s.blend.empty()) j["blend"] = s.blend;
    if (s.blackLevel != glm::dvec3(0.0))
        j["blackLevel"] = s.blackLevel.x == s.blackLevel.y && s.blackLevel.y == s.blackLevel.z ? Json(s.blackLevel.x)
                                                                                               : vec(s.blackLevel);
    return j;
}

Json trackingJson(const Tracking& t) {
    Json rows = Json::array();
    for (int r = 0; r < 4; ++r)
        rows.push_back(Json::array(
            {t.caveFromTracker[0][r], t.caveFromTracker[1][r], t.caveFromTracker[2][r], t.caveFromTracker[3][r]}));
    Json j;
    j["caveFromTracker"] = rows;
    j["latencyMs"] = t.latencyMs;
    if (t.volume) j["volume"] = Json::array({vec((*t.volume)[0]), vec((*t.volume)[1])});
    return j;
}

bool isFlat(const Json& j) {
    if (!j.is_array()) return false;
    for (const Json& e : j)
        if (e.is_structured()) return false;
    return true;
}

// As Json::dump(2), but an array of numbers on one line ([x, y, z]) and each row of a matrix on
// its own line, as people write them.
void write(const Json& j, const std::string& indent, std::string& out) {
    if (isFlat(j)) {
        out += "[";
        for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
        out += "]";
        return;
    }
    if (!j.is_structured()) {
        out += j.dump();
        return;
    }
    const std::string inner = indent + "  ";
    out += j.is_array() ? "[\n" : "{\n";
    std::size_t i = 0;
    for (auto it = j.begin(); it != j.end(); ++it, ++i) {
        out += (i ? ",\n" : "") + inner;
        if (j.is_object()) out += Json(it.key()).dump() + ": ";
        write(it.value(), inner, out);
    }
    out += "\n" + indent + (j.is_array() ? "]" : "}");
}

}  // namespace

std::string displayConfigJson(const DisplayConfig& config) {
    Json j;
    j["name"] = config.name;
    j["screens"] = Json::array();
    for (const Screen& s : config.screens) j["screens"].push_back(screenJson(s));
    const Viewer& v = config.viewer;
    const glm::dquat& q = v.headOrientation;
    j["viewer"] = {{"headPosition", vec(v.headPosition)},
                   {"headOrientation", Json::array({q.x, q.y, q.z, q.w})},
                   {"eyeSeparation", v.eyeSeparation},
                   {"near", v.near},
                   {"far", std::isinf(v.far) ? Json("infinite") : Json(v.far)}};
    j["stereo"] = std::string(toString(config.stereo));
    j["minEyeDistance"] = config.minEyeDistance;
    j["tracking"] = trackingJson(config.tracking);
    std::string out;
    write(j, "", out);
    return out + "\n";
}

}  // namespace cavewall::config
