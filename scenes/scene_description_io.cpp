// scene.json: which glTF files make a scene and how it is cut into cells.
//
// {
//   "name": "plant",                          optional; default: the folder's name
//   "models": [{                              at least one
//     "file": "plant.glb",                    glTF/GLB, relative to the scene.json folder
//     "metresPerUnit": 1,                     optional, default 1 (0.001 for files in mm), or
//     "units": "mm",                          instead: one of "m", "cm", "mm", "in", "ft"
//     "up": "y",                              optional, "y" (glTF) or "z" (Z-up files are turned to Y-up)
//     "matrix": [[1,0,0,0],[0,1,0,0],[0,0,1,0],[0,0,0,1]],   optional placement, rows as written
//     "position": [x,y,z], "rotation": {"yawDeg": 90}, "scale": 1,  or these instead of "matrix"
//     "structure": false,                     optional: every object of the file is structure
//     "structureNodes": ["Floor*", "Wall*"],  optional node-name patterns ('*' = any characters)
//     "splitMetres": 4                        optional: cut content objects wider than this (x or
//                                             z, at least 1024 triangles) into chunks of about
//                                             this size, one object each (scenes/mesh_split.h)
//   }],
//   "viewer": {"eyeHeight": 1.7, "headHeightRange": [1.2, 2.0]},   optional, metres
//   "planning": {"minZone": 2, "maxRes": 512},   optional: the smallest zone size (metres) and
//                                             largest baked texture side (texels) the walls are
//                                             planned and baked with unless a command says otherwise
//   "cells": [{"name": "A", "floorY": 0, "region": [[x,z], ...]}],  convex floor polygons (x, z);
//                                             either orientation in the file, stored counter-clockwise
//   "walls": [{"name": "AB", "kind": "virtual", "cells": ["A", "B"],          kind: virtual|portal
//              "lowerLeft": [x,y,z], "lowerRight": [x,y,z], "upperLeft": [x,y,z]}],
//   "realWalls": [{"name": "w1", "lowerLeft": ..., "lowerRight": ..., "upperLeft": ...}],
//   "walkPath": [[x,y,z], ...]                eye positions in the world frame
//   "walkBreaks": [i, ...]                    optional: walkPath indices that start a new piece
//   "wallPath": [[x,y,z], ...]                optional: a second path hugging the virtual walls
// }
// The placement maps file coordinates to the world: world = matrix * upAxis * metresPerUnit * p.
// A wall's front (normal = cross(lowerRight - lowerLeft, upperLeft - lowerLeft)) faces cells[0].
// Unknown keys are errors. Validation rules: scene_description_validate.cpp.
#include "scenes/scene_description_io.h"

#include "config/json_reader.h"

#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <limits>
#include <map>

namespace cavewall::scenes {
namespace {

using config::JsonNode;

ModelFile parseModel(const JsonNode& n) {
    n.expectKeys({"file", "metresPerUnit", "units", "up", "matrix", "position", "rotation", "scale", "structure",
                  "structureNodes", "splitMetres"});
    ModelFile m;
    m.file = n.at("file").string();
    if (m.file.empty()) n.at("file").fail("expected a file name, got an empty string");
    if (auto v = n.find("metresPerUnit")) m.metresPerUnit = v->number(1e-9, 1e9);
    if (auto v = n.find("units")) {
        if (n.has("metresPerUnit")) n.fail("give either 'units' or 'metresPerUnit', not both");
        const std::string u = v->oneOf({"m", "cm", "mm", "in", "ft"});
        m.metresPerUnit = u == "m" ? 1.0 : u == "cm" ? 0.01 : u == "mm" ? 0.001 : u == "in" ? 0.0254 : 0.3048;
    }
    if (auto v = n.find("up")) m.up = v->oneOf({"y", "z"}) == "z" ? UpAxis::Z : UpAxis::Y;
    const bool trs = n.has("position") || n.has("rotation") || n.has("scale");
    if (auto v = n.find("matrix")) {
        if (trs) n.fail("give either 'matrix' or 'position'/'rotation'/'scale', not both");
        m.worldFromFile = v->mat4Rows();
    } else if (trs) {
        glm::dmat4 t(1.0);
        if (auto p = n.find("position")) t = glm::translate(t, p->vec3());
        if (auto r = n.find("rotation")) t *= glm::mat4_cast(r->rotation());
        if (auto s = n.find("scale")) t = glm::scale(t, glm::dvec3(s->number(1e-9, 1e9)));
        m.worldFromFile = t;
    }
    if (auto v = n.find("structure")) m.structure = v->boolean();
    if (auto v = n.find("structureNodes"))
        for (const JsonNode& p : v->items()) m.structureNodes.push_back(p.string());
    if (auto v = n.find("splitMetres")) m.splitMetres = v->number(0.1, 1e6);
    return m;
}

// Sum of (x_i z_j - x_j z_i): negative for counter-clockwise seen from +Y (x right, -z up).
double orientationSum(const std::vector<glm::dvec2>& r) {
    double s = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
        const glm::dvec2 a = r[i], b = r[(i + 1) % r.size()];
        s += a.x * b.y - b.x * a.y;
    }
    return s;
}

Cell parseCell(const JsonNode& n) {
    n.expectKeys({"name", "floorY", "region"});
    Cell c;
    c.name = n.at("name").string();
    if (auto v = n.find("floorY")) c.floorY = v->number();
    for (const JsonNode& p : n.at("region").items()) c.region.push_back(p.vec2());
    if (orientationSum(c.region) > 0.0) std::reverse(c.region.begin(), c.region.end());
    return c;
}

void parseQuad(const JsonNode& n, glm::dvec3& ll, glm::dvec3& lr, glm::dvec3& ul) {
    ll = n.at("lowerLeft").vec3();
    lr = n.at("lowerRight").vec3();
    ul = n.at("upperLeft").vec3();
}

VirtualWall parseWall(const JsonNode& n, const std::map<std::string, int>& cells) {
    n.expectKeys({"name", "kind", "cells", "lowerLeft", "lowerRight", "upperLeft"});
    VirtualWall w;
    w.name = n.at("name").string();
    if (auto k = n.find("kind"))
        w.kind = k->oneOf({"virtual", "portal"}) == "portal" ? WallKind::Portal : WallKind::Virtual;
    const auto names = n.at("cells").items(2, 2);
    for (int i = 0; i < 2; ++i) {
        const std::string name = names[i].string();
        auto it = cells.find(name);
        if (it == cells.end()) {
            std::string list;
            for (const auto& [cell, _] : cells) list += (list.empty() ? "" : ", ") + cell;
            names[i].fail("cell '" + name + "' does not exist (expected one of: " + list + ")");
        }
        w.cells[i] = it->second;
    }
    parseQuad(n, w.lowerLeft, w.lowerRight, w.upperLeft);
    return w;
}

void parseViewer(const JsonNode& n, SceneDescription& d) {
    n.expectKeys({"eyeHeight", "headHeightRange"});
    if (auto v = n.find("eyeHeight")) d.eyeHeight = v->number(0.1, 10.0);
    if (auto v = n.find("headHeightRange")) {
        const auto r = v->items(2, 2);
        d.headHeightRange = {r[0].number(-1e6, 1e6), r[1].number(-1e6, 1e6)};
        if (!(d.headHeightRange.x < d.headHeightRange.y))
            v->fail("expected [low, high] with low < high, got [" + config::formatNumber(d.headHeightRange.x) + ", " +
                    config::formatNumber(d.headHeightRange.y) + "]");
    }
}

}  // namespace

SceneDescription parseSceneDescription(std::string_view jsonText, const std::string& source,
                                       const std::filesystem::path& folder) {
    const auto doc = config::JsonDocument::fromText(jsonText, source);
    const JsonNode root = doc.root();
    root.expectKeys(
        {"name", "models", "viewer", "planning", "cells", "walls", "realWalls", "walkPath", "walkBreaks", "wallPath"});
    SceneDescription d;
    d.folder = folder;
    d.name = root.has("name") ? root.at("name").string() : folder.lexically_normal().filename().string();
    if (d.name.empty() || d.name == ".") d.name = "scene";
    for (const JsonNode& m : root.at("models").items(1)) d.models.push_back(parseModel(m));
    if (auto v = root.find("viewer")) parseViewer(*v, d);
    if (auto v = root.find("planning")) {
        v->expectKeys({"minZone", "maxRes"});
        if (auto z = v->find("minZone")) d.planning.minZone = z->number(0.01, 1000.0);
        if (auto r = v->find("maxRes")) d.planning.maxRes = static_cast<int>(r->integer(16, 16384));
    }
    std::map<std::string, int> cellIndex;
    if (auto v = root.find("cells"))
        for (const JsonNode& c : v->items()) {
            d.cells.push_back(parseCell(c));
            if (!cellIndex.emplace(d.cells.back().name, static_cast<int>(d.cells.size()) - 1).second)
                c.at("name").fail("duplicate cell name '" + d.cells.back().name + "' (expected unique names)");
        }
    if (auto v = root.find("walls"))
        for (const JsonNode& w : v->items()) d.walls.push_back(parseWall(w, cellIndex));
    if (auto v = root.find("realWalls"))
        for (const JsonNode& w : v->items()) {
            w.expectKeys({"name", "lowerLeft", "lowerRight", "upperLeft"});
            RealWall r;
            r.name = w.at("name").string();
            parseQuad(w, r.lowerLeft, r.lowerRight, r.upperLeft);
            d.realWalls.push_back(r);
        }
    if (auto v = root.find("walkPath"))
        for (const JsonNode& p : v->items()) d.walkPath.push_back(p.vec3());
    if (auto v = root.find("walkBreaks"))
        for (const JsonNode& i : v->items()) d.walkBreaks.push_back(i.integer(1, std::numeric_limits<int>::max()));
    if (auto v = root.find("wallPath"))
        for (const JsonNode& p : v->items()) d.wallPath.push_back(p.vec3());
    return d;
}

SceneDescription loadSceneDescription(const std::filesystem::path& path) {
    std::error_code ec;
    const std::filesystem::path file = std::filesystem::is_directory(path, ec) ? path / "scene.json" : path;
    const std::string text = config::readTextFile(file);
    const std::filesystem::path folder = file.parent_path().empty() ? "." : file.parent_path();
    SceneDescription d = parseSceneDescription(text, file.string(), folder);
    validateSceneDescription(d, file.string());
    return d;
}

namespace {

nlohmann::json vecJson(glm::dvec3 v) { return {v.x, v.y, v.z}; }

nlohmann::json quadJson(const std::string& name, glm::dvec3 ll, glm::dvec3 lr, glm::dvec3 ul) {
    return {{"name", name}, {"lowerLeft", vecJson(ll)}, {"lowerRight", vecJson(lr)}, {"upperLeft", vecJson(ul)}};
}

nlohmann::json modelJson(const ModelFile& m) {
    nlohmann::json j = {{"file", m.file.generic_string()}};
    if (m.metresPerUnit != 1.0) j["metresPerUnit"] = m.metresPerUnit;
    if (m.up == UpAxis::Z) j["up"] = "z";
    if (m.worldFromFile != glm::dmat4(1.0)) {
        nlohmann::json rows = nlohmann::json::array();
        for (int r = 0; r < 4; ++r)
            rows.push_back(
                {m.worldFromFile[0][r], m.worldFromFile[1][r], m.worldFromFile[2][r], m.worldFromFile[3][r]});
        j["matrix"] = rows;
    }
    if (m.structure) j["structure"] = true;
    if (!m.structureNodes.empty()) j["structureNodes"] = m.structureNodes;
    if (m.splitMetres > 0.0) j["splitMetres"] = m.splitMetres;
    return j;
}

// Pretty JSON with arrays of scalars on one line ("lowerLeft": [0, 0, 2]), so files stay short
// and readable. Scalars use nlohmann's printing: the shortest text that reads back exactly.
void dumpCompact(const nlohmann::json& j, int indent, std::string& out) {
    const std::string pad(static_cast<std::size_t>(indent) + 2, ' ');
    if (j.is_object() && !j.empty()) {
        out += "{\n";
        std::size_t i = 0;
        for (const auto& [key, value] : j.items()) {
            out += pad + nlohmann::json(key).dump() + ": ";
            dumpCompact(value, indent + 2, out);
            out += ++i < j.size() ? ",\n" : "\n";
        }
        out += std::string(static_cast<std::size_t>(indent), ' ') + "}";
        return;
    }
    if (j.is_array() && !j.empty() &&
        !std::all_of(j.begin(), j.end(), [](const auto& e) { return e.is_primitive(); })) {
        out += "[\n";
        for (std::size_t i = 0; i < j.size(); ++i) {
            out += pad;
            dumpCompact(j[i], indent + 2, out);
            out += i + 1 < j.size() ? ",\n" : "\n";
        }
        out += std::string(static_cast<std::size_t>(indent), ' ') + "]";
        return;
    }
    if (j.is_array()) {
        out += "[";
        for (std::size_t i = 0; i < j.size(); ++i) out += (i ? ", " : "") + j[i].dump();
        out += "]";
        return;
    }
    out += j.dump();
}

}  // namespace

std::string writeSceneDescription(const SceneDescription& d) {
    // nlohmann::json prints doubles in the shortest form that reads back exactly, and keeps
    // object keys sorted: the same description always gives the same bytes.
    nlohmann::json j;
    j["name"] = d.name;
    for (const ModelFile& m : d.models) j["models"].push_back(modelJson(m));
    j["viewer"] = {{"eyeHeight", d.eyeHeight}, {"headHeightRange", {d.headHeightRange.x, d.headHeightRange.y}}};
    if (d.planning.minZone > 0.0) j["planning"]["minZone"] = d.planning.minZone;  // optional: others keep their bytes
    if (d.planning.maxRes > 0) j["planning"]["maxRes"] = d.planning.maxRes;
    j["cells"] = nlohmann::json::array();
    for (const Cell& c : d.cells) {
        nlohmann::json region = nlohmann::json::array();
        for (glm::dvec2 p : c.region) region.push_back({p.x, p.y});
        j["cells"].push_back({{"name", c.name}, {"floorY", c.floorY}, {"region", region}});
    }
    j["walls"] = nlohmann::json::array();
    for (const VirtualWall& w : d.walls) {
        nlohmann::json wj = quadJson(w.name, w.lowerLeft, w.lowerRight, w.upperLeft);
        wj["kind"] = w.kind == WallKind::Portal ? "portal" : "virtual";
        auto cellName = [&](int i) { return i >= 0 && i < static_cast<int>(d.cells.size()) ? d.cells[i].name : "?"; };
        wj["cells"] = {cellName(w.cells[0]), cellName(w.cells[1])};
        j["walls"].push_back(wj);
    }
    j["realWalls"] = nlohmann::json::array();
    for (const RealWall& w : d.realWalls)
        j["realWalls"].push_back(quadJson(w.name, w.lowerLeft, w.lowerRight, w.upperLeft));
    j["walkPath"] = nlohmann::json::array();
    for (glm::dvec3 p : d.walkPath) j["walkPath"].push_back(vecJson(p));
    if (!d.walkBreaks.empty()) j["walkBreaks"] = d.walkBreaks;  // optional, as wallPath
    if (!d.wallPath.empty()) {                                  // optional: scenes without one keep their bytes
        j["wallPath"] = nlohmann::json::array();
        for (glm::dvec3 p : d.wallPath) j["wallPath"].push_back(vecJson(p));
    }
    std::string out;
    dumpCompact(j, 0, out);
    return out + "\n";
}

}  // namespace cavewall::scenes
