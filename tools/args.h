#pragma once
// Command-line arguments of one cavewall subcommand: "--flag value", "--switch" and positional
// words. Every lookup validates and throws cavewall::Error with the flag's name, what was
// expected and what was given. Unknown flags are errors (expectFlags).

#include "config/error.h"

#include <glm/glm.hpp>

#include <array>
#include <filesystem>
#include <initializer_list>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace cavewall::tools {

// "--flag: expected a or b, got 'x'" (or "expected one of a, b, c" for more than two words).
Error choiceError(std::string_view flag, const std::vector<std::string_view>& expected, std::string_view got);

class Args {
public:
    // `switches` are flags that take no value; every other "--name" takes the next word.
    Args(std::vector<std::string> words, std::initializer_list<std::string_view> switches);

    // Fails on any flag not in `allowed` (names without "--").
    void expectFlags(std::initializer_list<std::string_view> allowed) const;
    void expectFlags(const std::vector<std::string_view>& allowed) const;

    bool has(std::string_view flag) const;
    // For a flag renamed and still accepted under its old name for one release: `oldName` when
    // that was given, else `flag`, so that lookups and their messages name the word the user
    // typed. Both given: an error.
    std::string_view renamed(std::string_view flag, std::string_view oldName) const;
    std::optional<std::string> get(std::string_view flag) const;
    std::string require(std::string_view flag) const;
    std::string getOr(std::string_view flag, std::string fallback) const;
    // A path; an empty word is an error ("--cache: expected a path, got an empty word"), never
    // a silent fallback to a default folder.
    std::optional<std::filesystem::path> path(std::string_view flag) const;
    // For a flag that is a command of its own (`bench --stability`): throws "<command>: --flag
    // runs alone (expected no other flags or words, got --x)" when anything else is given.
    void expectAlone(std::string_view flag, std::string_view command) const;
    double number(std::string_view flag, double fallback, double lo, double hi) const;
    long integer(std::string_view flag, long fallback, long lo, long hi) const;
    // The value whose word in `names` the flag gives, or `fallback` when the flag is absent.
    // Anything else is an error naming the flag, the words it takes and what was given.
    template <typename E, std::size_t N>
    E choice(std::string_view flag, const std::array<std::pair<std::string_view, E>, N>& names, E fallback) const {
        const std::optional<std::string> word = get(flag);
        if (!word) return fallback;
        std::vector<std::string_view> words;
        for (const auto& [name, value] : names) {
            if (name == *word) return value;
            words.push_back(name);
        }
        throw choiceError(flag, words, *word);
    }
    // "x,y,z" in metres (or any unit the flag states); all three finite.
    std::optional<glm::dvec3> vec3(std::string_view flag) const;
    // "WxH" in pixels, each an integer in [lo, hi].
    std::optional<glm::ivec2> size(std::string_view flag, int lo, int hi) const;

    const std::vector<std::string>& positional() const { return _positional; }
    // Throws "<command>: unexpected word 'x' (expected only --flags)" when there is any
    // positional word, for commands that take none.
    void expectNoPositional(std::string_view command) const;
    // The positional word `i`, or an error naming `what` when it is missing.
    const std::string& positional(std::size_t i, std::string_view what) const;

private:
    std::map<std::string, std::string, std::less<>> _flags;
    std::vector<std::string> _positional;
    std::string _missingValue;  // a last flag that takes a value but has none
};

// Parses a finite number; `what` names the source in the error message.
double parseNumber(std::string_view text, std::string_view what);

}  // namespace cavewall::tools
