#pragma once
// Reading JSON input files with errors that say where, what, and expected vs got.
//
// A JsonDocument owns a parsed file; JsonNode is a cheap view of one value in it that knows
// its file name and JSON path (for example "screens[1].upperLeft"). Every accessor checks the
// type and, for numbers, finiteness and range, and throws cavewall::Error with a message such
// as "lab.json: screens[1].resolution[0]: expected a number in [1, 16384], got 0".
//
// Objects are checked for unknown keys with expectKeys(): a misspelt key is an error, never
// silently ignored.

#include "config/error.h"

#include <glm/glm.hpp>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace cavewall::config {

class JsonNode {
public:
    JsonNode(const nlohmann::json& value, const std::string& source, std::string path);

    const std::string& path() const { return _path; }
    const std::string& source() const { return *_source; }
    const nlohmann::json& raw() const { return *_value; }

    // Throws Error("<source>: <path>: <what>").
    [[noreturn]] void fail(const std::string& what) const;
    // "<source>: <path>" (or just "<source>" at the root), for messages built elsewhere.
    std::string where() const;

    // Objects. at() requires the key; find() returns nullopt when it is absent.
    // expectKeys() fails on any key not listed, naming the allowed ones.
    JsonNode at(std::string_view key) const;
    std::optional<JsonNode> find(std::string_view key) const;
    bool has(std::string_view key) const;
    void expectObject() const;
    void expectKeys(std::initializer_list<std::string_view> allowed) const;

    // Arrays. items() fails unless this is an array, with optional size limits.
    std::vector<JsonNode> items(std::size_t minSize = 0, std::size_t maxSize = SIZE_MAX) const;

    // Scalars. Numbers must be finite; the ranges are inclusive.
    double number() const;
    double number(double lo, double hi) const;
    int integer(int lo, int hi) const;
    bool boolean() const;
    std::string string() const;
    // A string that must be one of `choices`; the message lists them.
    std::string oneOf(std::initializer_list<std::string_view> choices) const;

    // Fixed-size numeric arrays.
    glm::dvec2 vec2() const;
    glm::dvec3 vec3() const;
    glm::ivec2 ivec2(int lo, int hi) const;
    // A 4x4 matrix as 4 rows of 4 numbers (row-major, as people write matrices), so
    // [[1,0,0,tx],[0,1,0,ty],[0,0,1,tz],[0,0,0,1]] translates by t.
    glm::dmat4 mat4Rows() const;
    // A rotation as {"yawDeg","pitchDeg","rollDeg"} (Y, then X, then Z; intrinsic) or as a unit
    // quaternion [x, y, z, w]; a quaternion is normalised (unless unit within 1e-12, so that a
    // written one reads back bit for bit) and must have a length within 1e-3 of 1.
    glm::dquat rotation() const;

private:
    void expectType(bool ok, const char* expected) const;
    std::string child(std::string_view key) const;

    const nlohmann::json* _value;
    const std::string* _source;
    std::string _path;
};

// A parsed JSON file or string. Keep it alive while its JsonNodes are used.
class JsonDocument {
public:
    // Reads and parses a file; throws Error naming the file for unreadable or non-JSON input
    // (with line and column for syntax errors).
    static JsonDocument fromFile(const std::filesystem::path& file);
    // Parses text; `sourceName` stands for the file in messages.
    static JsonDocument fromText(std::string_view text, std::string sourceName);

    JsonNode root() const { return JsonNode(_json, _source, ""); }
    const std::string& source() const { return _source; }

private:
    nlohmann::json _json;
    std::string _source;
};

// Reads a whole file; throws Error naming the file when it cannot be opened or read.
std::string readTextFile(const std::filesystem::path& file);

// A short description of a JSON value for "got ..." in messages: numbers and short strings
// verbatim, otherwise the type ("an object", "an array of 3").
std::string describeJson(const nlohmann::json& value);

// Formats a double for messages: shortest form that reads back the same, at most 6 significant
// digits for readability ("0.064", "1e-09", "inf").
std::string formatNumber(double value);
// Formats a double with `decimals` digits after the point ("59.6", "0.001"); "inf", "-inf" and
// "nan" for those.
std::string formatFixed(double value, int decimals);

}  // namespace cavewall::config
