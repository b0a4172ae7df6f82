#include "tools/args.h"

#include "tools/commands.h"
#include "walls/texture_blocks.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace cavewall::tools {

Args::Args(std::vector<std::string> words, std::initializer_list<std::string_view> switches) {
    for (std::size_t i = 0; i < words.size(); ++i) {
        const std::string& w = words[i];
        if (w.size() < 3 || w.rfind("--", 0) != 0) {
            _positional.push_back(w);
            continue;
        }
        std::string name = w.substr(2), value;
        if (auto eq = name.find('='); eq != std::string::npos) {
            value = name.substr(eq + 1);
            name.resize(eq);
        } else if (std::find(switches.begin(), switches.end(), name) == switches.end()) {
            // Reported later (expectFlags, get): an unknown last flag is unknown first.
            if (i + 1 >= words.size())
                _missingValue = name;
            else
                value = words[++i];
        }
        if (_flags.count(name)) throw Error("--" + name + ": given more than once");
        _flags[name] = value;
    }
}

void Args::expectFlags(std::initializer_list<std::string_view> allowed) const {
    expectFlags(std::vector<std::string_view>(allowed));
}

void Args::expectFlags(const std::vector<std::string_view>& allowed) const {
    for (const auto& [name, _] : _flags) {
        if (std::find(allowed.begin(), allowed.end(), name) != allowed.end()) continue;
        std::string list;
        for (auto a : allowed) list += (list.empty() ? "--" : ", --") + std::string(a);
        throw Error("--" + name + ": unknown flag (expected one of: " + list + ")");
    }
    if (!_missingValue.empty()) throw Error("--" + _missingValue + ": expected a value after the flag, got nothing");
}

void Args::expectNoPositional(std::string_view command) const {
    if (!_positional.empty())
        throw Error(std::string(command) + ": unexpected word '" + _positional[0] + "' (expected only --flags)");
}

bool Args::has(std::string_view flag) const { return _flags.find(flag) != _flags.end(); }

std::string_view Args::renamed(std::string_view flag, std::string_view oldName) const {
    if (has(flag) && has(oldName))
        throw Error("--" + std::string(flag) + " and --" + std::string(oldName) +
                    ": expected one of them, got both (--" + std::string(oldName) + " is the old name of --" +
                    std::string(flag) + ")");
    return has(oldName) ? oldName : flag;
}

std::optional<std::string> Args::get(std::string_view flag) const {
    auto it = _flags.find(flag);
    if (it == _flags.end()) return std::nullopt;
    if (flag == _missingValue) throw Error("--" + _missingValue + ": expected a value after the flag, got nothing");
    return it->second;
}

std::string Args::require(std::string_view flag) const {
    auto v = get(flag);
    if (!v || v->empty()) throw Error("--" + std::string(flag) + ": required flag is missing");
    return *v;
}

std::optional<std::filesystem::path> Args::path(std::string_view flag) const {
    const std::optional<std::string> v = get(flag);
    if (v && v->empty()) throw Error("--" + std::string(flag) + ": expected a path, got an empty word");
    return v ? std::optional<std::filesystem::path>(*v) : std::nullopt;
}

void Args::expectAlone(std::string_view flag, std::string_view command) const {
    if (!has(flag)) return;
    std::string other;
    for (const auto& [name, _] : _flags)
        if (name != flag) other += (other.empty() ? "--" : ", --") + name;
    for (const std::string& word : _positional) other += (other.empty() ? "'" : ", '") + word + "'";
    if (!other.empty())
        throw Error(std::string(command) + ": --" + std::string(flag) +
                    " runs alone (expected no other flags or words, got " + other + ")");
}

std::string Args::getOr(std::string_view flag, std::string fallback) const {
    auto v = get(flag);
    return v ? *v : fallback;
}

double parseNumber(std::string_view text, std::string_view what) {
    double v = 0.0;
    const char* end = text.data() + text.size();
    auto [ptr, ec] = std::from_chars(text.data(), end, v);
    if (ec != std::errc() || ptr != end || !std::isfinite(v))
        throw Error(std::string(what) + ": expected a finite number, got '" + std::string(text) + "'");
    return v;
}

double Args::number(std::string_view flag, double fallback, double lo, double hi) const {
    auto s = get(flag);
    if (!s) return fallback;
    const std::string what = "--" + std::string(flag);
    const double v = parseNumber(*s, what);
    if (v < lo || v > hi)
        throw Error(what + ": expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], got " +
                    *s);
    return v;
}

long Args::integer(std::string_view flag, long fallback, long lo, long hi) const {
    auto s = get(flag);
    if (!s) return fallback;
    long v = 0;
    auto [ptr, ec] = std::from_chars(s->data(), s->data() + s->size(), v);
    if (ec != std::errc() || ptr != s->data() + s->size() || v < lo || v > hi)
        throw Error("--" + std::string(flag) + ": expected an integer in [" + std::to_string(lo) + ", " +
                    std::to_string(hi) + "], got '" + *s + "'");
    return v;
}

std::optional<glm::dvec3> Args::vec3(std::string_view flag) const {
    auto s = get(flag);
    if (!s) return std::nullopt;
    const std::string what = "--" + std::string(flag);
    glm::dvec3 v;
    std::size_t start = 0;
    for (int i = 0; i < 3; ++i) {
        const std::size_t comma = s->find(',', start);
        if ((i < 2) != (comma != std::string::npos))
            throw Error(what + ": expected three comma-separated numbers x,y,z, got '" + *s + "'");
        v[i] = parseNumber(std::string_view(*s).substr(start, comma - start), what);
        start = comma + 1;
    }
    return v;
}

std::optional<glm::ivec2> Args::size(std::string_view flag, int lo, int hi) const {
    const std::optional<std::string> s = get(flag);
    if (!s) return std::nullopt;
    const auto fail = [&] {
        return Error("--" + std::string(flag) + ": expected WxH with integers in [" + std::to_string(lo) + ", " +
                     std::to_string(hi) + "] (e.g. 1280x720), got '" + *s + "'");
    };
    const std::size_t x = s->find('x');
    if (x == std::string::npos) throw fail();
    glm::ivec2 v;
    const char* begin = s->data();
    for (int i = 0; i < 2; ++i) {
        const char* from = begin + (i == 0 ? 0 : x + 1);
        const char* to = begin + (i == 0 ? x : s->size());
        auto [ptr, ec] = std::from_chars(from, to, v[i]);
        if (ec != std::errc() || ptr != to || from == to || v[i] < lo || v[i] > hi) throw fail();
    }
    return v;
}

Error choiceError(std::string_view flag, const std::vector<std::string_view>& expected, std::string_view got) {
    std::string list;
    for (std::size_t i = 0; i < expected.size(); ++i) {
        if (i > 0) list += expected.size() == 2 ? " or " : ", ";
        list += expected[i];
    }
    return Error("--" + std::string(flag) + ": expected " + (expected.size() > 2 ? "one of " : "") + list + ", got '" +
                 std::string(got) + "'");
}

const std::string& Args::positional(std::size_t i, std::string_view what) const {
    if (i >= _positional.size()) throw Error("missing argument: expected " + std::string(what));
    return _positional[i];
}

}  // namespace cavewall::tools

namespace {

constexpr bool defaultTextureFormatNamed(std::string_view name) {
    for (const auto& [word, format] : cavewall::walls::kTextureFormatNames)
        if (format == cavewall::walls::kDefaultTextureFormat) return word == name;
    return false;
}
static_assert(defaultTextureFormatNamed(DEFAULT_TEXTURE_FORMAT),
              "DEFAULT_TEXTURE_FORMAT (tools/commands.h) must name walls::kDefaultTextureFormat");

}  // namespace
