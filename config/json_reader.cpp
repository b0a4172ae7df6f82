#include "config/json_reader.h"

#include "config/json_depth.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace cavewall::config {

std::string formatNumber(double value) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[32];
    std::snprintf(buffer, sizeof buffer, "%.6g", value);
    return buffer;
}

std::string formatFixed(double value, int decimals) {
    if (std::isnan(value)) return "nan";
    if (std::isinf(value)) return value > 0 ? "inf" : "-inf";
    char buffer[64];
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, value);
    return buffer;
}

std::string describeJson(const nlohmann::json& value) {
    switch (value.type()) {
        case nlohmann::json::value_t::null: return "null";
        case nlohmann::json::value_t::boolean: return value.get<bool>() ? "true" : "false";
        case nlohmann::json::value_t::number_integer:
        case nlohmann::json::value_t::number_unsigned:
        case nlohmann::json::value_t::number_float: return formatNumber(value.get<double>());
        case nlohmann::json::value_t::string: {
            const auto& s = value.get_ref<const std::string&>();
            return s.size() <= 40 ? "\"" + s + "\"" : "a string of " + std::to_string(s.size()) + " characters";
        }
        case nlohmann::json::value_t::array: return "an array of " + std::to_string(value.size());
        case nlohmann::json::value_t::object: return "an object";
        default: return "an unsupported value";
    }
}

JsonNode::JsonNode(const nlohmann::json& value, const std::string& source, std::string path)
    : _value(&value), _source(&source), _path(std::move(path)) {}

std::string JsonNode::where() const { return _path.empty() ? *_source : *_source + ": " + _path; }

void JsonNode::fail(const std::string& what) const { throw Error(where() + ": " + what); }

void JsonNode::expectType(bool ok, const char* expected) const {
    if (!ok) fail(std::string("expected ") + expected + ", got " + describeJson(*_value));
}

std::string JsonNode::child(std::string_view key) const {
    return _path.empty() ? std::string(key) : _path + "." + std::string(key);
}

void JsonNode::expectObject() const { expectType(_value->is_object(), "an object"); }

bool JsonNode::has(std::string_view key) const { return _value->is_object() && _value->contains(key); }

JsonNode JsonNode::at(std::string_view key) const {
    expectObject();
    auto it = _value->find(key);
    if (it == _value->end()) fail("missing required key '" + std::string(key) + "'");
    return JsonNode(*it, *_source, child(key));
}

std::optional<JsonNode> JsonNode::find(std::string_view key) const {
    expectObject();
    auto it = _value->find(key);
    if (it == _value->end()) return std::nullopt;
    return JsonNode(*it, *_source, child(key));
}

void JsonNode::expectKeys(std::initializer_list<std::string_view> allowed) const {
    expectObject();
    for (const auto& [key, _] : _value->items()) {
        bool known = false;
        for (auto a : allowed) known = known || a == key;
        if (known) continue;
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
        fail("unknown key '" + key + "' (expected one of: " + list + ")");
    }
}

std::vector<JsonNode> JsonNode::items(std::size_t minSize, std::size_t maxSize) const {
    expectType(_value->is_array(), "an array");
    const std::size_t n = _value->size();
    if (n < minSize || n > maxSize) {
        std::string expected = minSize == maxSize    ? std::to_string(minSize)
                               : maxSize == SIZE_MAX ? "at least " + std::to_string(minSize)
                                                     : std::to_string(minSize) + " to " + std::to_string(maxSize);
        fail("expected an array of " + expected + " elements, got " + std::to_string(n));
    }
    std::vector<JsonNode> out;
    out.reserve(n);
    for (std::size_t i = 0; i < n; ++i) out.emplace_back((*_value)[i], *_source, _path + "[" + std::to_string(i) + "]");
    return out;
}

double JsonNode::number() const {
    expectType(_value->is_number(), "a number");
    const double v = _value->get<double>();
    if (!std::isfinite(v)) fail("expected a finite number, got " + formatNumber(v));
    return v;
}

double JsonNode::number(double lo, double hi) const {
    const double v = number();
    if (v < lo || v > hi)
        fail("expected a number in [" + formatNumber(lo) + ", " + formatNumber(hi) + "], got " + formatNumber(v));
    return v;
}

int JsonNode::integer(int lo, int hi) const {
    const double v = number();
    if (v != std::floor(v)) fail("expected an integer, got " + formatNumber(v));
    if (v < lo || v > hi)
        fail("expected an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " + formatNumber(v));
    return static_cast<int>(v);
}

bool JsonNode::boolean() const {
    expectType(_value->is_boolean(), "true or false");
    return _value->get<bool>();
}

std::string JsonNode::string() const {
    expectType(_value->is_string(), "a string");
    return _value->get<std::string>();
}

std::string JsonNode::oneOf(std::initializer_list<std::string_view> choices) const {
    std::string s = string();
    std::string list;
    for (auto c : choices) {
        if (c == s) return s;
        list += (list.empty() ? "\"" : ", \"") + std::string(c) + "\"";
    }
    fail("expected one of " + list + ", got \"" + s + "\"");
}

glm::dvec2 JsonNode::vec2() const {
    auto v = items(2, 2);
    return {v[0].number(), v[1].number()};
}

glm::dvec3 JsonNode::vec3() const {
    auto v = items(3, 3);
    return {v[0].number(), v[1].number(), v[2].number()};
}

glm::ivec2 JsonNode::ivec2(int lo, int hi) const {
    auto v = items(2, 2);
    return {v[0].integer(lo, hi), v[1].integer(lo, hi)};
}

glm::dmat4 JsonNode::mat4Rows() const {
    auto rows = items(4, 4);
    glm::dmat4 m(1.0);
    for (int r = 0; r < 4; ++r) {
        auto cols = rows[r].items(4, 4);
        for (int c = 0; c < 4; ++c) m[c][r] = cols[c].number();
    }
    return m;
}

glm::dquat JsonNode::rotation() const {
    if (_value->is_array()) {
        auto v = items(4, 4);
        glm::dquat q(v[3].number(), v[0].number(), v[1].number(), v[2].number());
        const double len = glm::length(q);
        if (std::abs(len - 1.0) > 1e-3)
            fail("expected a unit quaternion [x, y, z, w], got length " + formatNumber(len));
        // A quaternion that is already unit (as written by displayConfigJson) reads back unchanged.
        return std::abs(len - 1.0) <= 1e-12 ? q : q / len;
    }
    expectKeys({"yawDeg", "pitchDeg", "rollDeg"});
    auto angle = [&](const char* key) {
        auto n = find(key);
        return n ? glm::radians(n->number(-360.0, 360.0)) : 0.0;
    };
    return glm::angleAxis(angle("yawDeg"), glm::dvec3(0, 1, 0)) *
           glm::angleAxis(angle("pitchDeg"), glm::dvec3(1, 0, 0)) *
           glm::angleAxis(angle("rollDeg"), glm::dvec3(0, 0, 1));
}

std::string readTextFile(const std::filesystem::path& file) {
    std::error_code ec;
    if (std::filesystem::is_directory(file, ec))
        throw Error(file.string() + ": cannot read (expected a file, got a directory)");
    std::ifstream in(file, std::ios::binary);
    if (!in) throw Error(file.string() + ": cannot open the file for reading (missing or no permission)");
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw Error(file.string() + ": read error");
    return text.str();
}

JsonDocument JsonDocument::fromFile(const std::filesystem::path& file) {
    return fromText(readTextFile(file), file.string());
}

JsonDocument JsonDocument::fromText(std::string_view text, std::string sourceName) {
    JsonDocument doc;
    doc._source = std::move(sourceName);
    checkJsonDepth(text, doc._source);
    try {
        doc._json = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        // e.what() reads "[json.exception.parse_error.101] parse error at line 3, column 5: ..."
        // or "[json.exception.out_of_range.406] number overflow parsing '1e999'".
        std::string what = e.what();
        auto at = what.find("at line");
        if (at == std::string::npos) at = what.find("] ") == std::string::npos ? 0 : what.find("] ") + 2;
        throw Error(doc._source + ": not valid JSON: " + what.substr(at));
    }
    return doc;
}

}  // namespace cavewall::config
